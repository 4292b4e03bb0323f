package org.fdnet.logger.cache;

import java.util.Arrays;
import java.util.List;

/**
 * An event container (thesis, chapter 4 IV): an array indexed by node id whose entries hold the node's
 * events sorted by time. Not thread-safe: {@link EventCache} guards it.
 */
class EventContainer {
    private NodeTimeline[] index = new NodeTimeline[64];
    private long events;

    void add(CachedEvent e) {
        timeline(e.sourceId(), true).add(e);
        events++;
    }

    long size() {
        return events;
    }

    void adjustSize(int delta) {
        events += delta;
    }

    /** Events of one node with {@code from <= time <= to}, in time order. */
    void range(int sourceId, long from, long to, List<CachedEvent> out) {
        NodeTimeline t = timeline(sourceId, false);
        if (t != null) {
            t.range(from, to, out);
        }
    }

    /** The newest time of this node that left memory ({@code Long.MIN_VALUE}: none). */
    long evictedUpTo(int sourceId) {
        NodeTimeline t = timeline(sourceId, false);
        return t == null ? Long.MIN_VALUE : t.evictedUpTo();
    }

    /** Lets the node's committed, unmonitored head events go; returns the bytes freed. */
    long evict(int sourceId) {
        NodeTimeline t = timeline(sourceId, false);
        if (t == null) {
            return 0;
        }
        int before = t.size();
        long freed = t.evictHead();
        events -= before - t.size();
        return freed;
    }

    final NodeTimeline timeline(int sourceId, boolean create) {
        if (sourceId < 0) {
            throw new IllegalArgumentException("negative source id " + sourceId);
        }
        if (sourceId >= index.length) {
            if (!create) {
                return null;
            }
            index = Arrays.copyOf(index, Math.max(index.length * 2, sourceId + 1));
        }
        NodeTimeline t = index[sourceId];
        if (t == null && create) {
            t = new NodeTimeline();
            index[sourceId] = t;
        }
        return t;
    }
}
