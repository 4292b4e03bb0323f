package org.fdnet.logger.cache;

import java.util.ArrayList;
import java.util.concurrent.atomic.AtomicReferenceArray;
import org.fdnet.event.NetworkEvent;

/**
 * An event container (thesis, chapter 4 IV): an array indexed by node id whose entries hold the node's
 * events sorted by time. Changes ({@link #add}, {@link #evict}) and the event count are guarded by
 * {@link EventCache}'s lock. {@link #range} needs no lock: timelines are created under the cache's lock and
 * published through an {@link AtomicReferenceArray} (itself published through a volatile field when it grows),
 * are never removed, and guard themselves.
 */
class EventContainer {
    private volatile AtomicReferenceArray<NodeTimeline> index = new AtomicReferenceArray<>(64);
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

    /**
     * Adds the events of one node with {@code from <= time <= to} to {@code out}, in time order, and returns
     * the newest time of the node that had left memory at that instant ({@code Long.MIN_VALUE}: none). Safe
     * without the cache's lock.
     */
    long range(int sourceId, long from, long to, ArrayList<CachedEvent> out) {
        NodeTimeline t = timeline(sourceId, false);
        return t == null ? Long.MIN_VALUE : t.range(from, to, out);
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

    /** The node's timeline; {@code create} only with the cache's lock held (one creator at a time). */
    final NodeTimeline timeline(int sourceId, boolean create) {
        if (sourceId < 0) {
            throw new IllegalArgumentException("negative source id " + sourceId);
        }
        AtomicReferenceArray<NodeTimeline> current = index;
        if (sourceId >= current.length()) {
            if (!create) {
                return null;
            }
            current = grown(current, Math.max(current.length() * 2, sourceId + 1));
        }
        NodeTimeline t = current.get(sourceId);
        if (t == null && create) {
            t = new NodeTimeline();
            current.set(sourceId, t);
        }
        return t;
    }

    private AtomicReferenceArray<NodeTimeline> grown(AtomicReferenceArray<NodeTimeline> old, int length) {
        AtomicReferenceArray<NodeTimeline> bigger = new AtomicReferenceArray<>(length);
        for (int i = 0; i < old.length(); i++) {
            bigger.set(i, old.get(i));
        }
        index = bigger;
        return bigger;
    }
}
