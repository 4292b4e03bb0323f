package org.fdnet.logger.cache;

/**
 * Someone monitoring nodes (a viewer connection). {@link #offer} is called under the cache's lock and
 * must only enqueue; the subscriber sends on its own thread and then calls
 * {@link EventCache#delivered} so the events may leave memory.
 */
public interface MonitorSubscriber {
    void offer(CachedEvent event);
}
