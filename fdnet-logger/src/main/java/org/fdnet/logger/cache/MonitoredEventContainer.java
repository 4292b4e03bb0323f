package org.fdnet.logger.cache;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The event container with monitoring (thesis, chapter 4 IV): the same node-then-time index, duplicated —
 * one index for events still waiting to be sent to a node's monitors, the inherited one for all. An event
 * whose node has monitors when it arrives is offered to each of them and stays "monitored" until every one
 * has sent it ({@link #delivered}) or stopped monitoring; until then it cannot leave memory, even when
 * committed. Not thread-safe: {@link EventCache} guards it.
 */
final class MonitoredEventContainer extends EventContainer {
    private final EventContainer monitoredIndex = new EventContainer();
    private final Map<Integer, List<MonitorSubscriber>> monitors = new HashMap<>();

    @Override
    void add(CachedEvent e) {
        super.add(e);
        List<MonitorSubscriber> subs = monitors.get(e.sourceId());
        if (subs != null && !subs.isEmpty()) {
            e.pendingMonitors = subs.size();
            monitoredIndex.add(e);
            for (MonitorSubscriber s : subs) {
                s.offer(e);
            }
        }
    }

    void subscribe(MonitorSubscriber subscriber, int sourceId) {
        List<MonitorSubscriber> subs = monitors.computeIfAbsent(sourceId, k -> new ArrayList<>());
        if (!subs.contains(subscriber)) {
            subs.add(subscriber);
        }
    }

    boolean unsubscribe(MonitorSubscriber subscriber, int sourceId) {
        List<MonitorSubscriber> subs = monitors.get(sourceId);
        boolean removed = subs != null && subs.remove(subscriber);
        if (subs != null && subs.isEmpty()) {
            monitors.remove(sourceId);
        }
        return removed;
    }

    int monitorCount() {
        int n = 0;
        for (List<MonitorSubscriber> subs : monitors.values()) {
            n += subs.size();
        }
        return n;
    }

    long monitoredEvents() {
        return monitoredIndex.size();
    }

    /** One monitor is done with the event (sent, or stopped monitoring); returns the bytes freed. */
    long delivered(CachedEvent e) {
        if (e.pendingMonitors <= 0) {
            return 0;
        }
        if (--e.pendingMonitors == 0) {
            NodeTimeline t = monitoredIndex.timeline(e.sourceId(), false);
            if (t != null && t.remove(e)) {
                monitoredIndex.adjustSize(-1);
            }
            return evict(e.sourceId());
        }
        return 0;
    }
}
