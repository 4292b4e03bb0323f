package org.fdnet.logger.server;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.fdnet.event.wire.ErrorCode;
import org.fdnet.event.wire.Protocol;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.cache.MonitorSubscriber;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One viewer's live stream: the cache offers it each new event of the monitored nodes; its own thread
 * sends them as MONITOR_EVENTS and then tells the cache they were delivered (so they may leave memory).
 * A viewer that falls {@link #MAX_QUEUED} events behind is disconnected: a stalled viewer must not hold the
 * cache, and through it the cores, hostage.
 */
final class MonitorStream implements MonitorSubscriber {
    private static final Logger LOG = LoggerFactory.getLogger(MonitorStream.class);
    static final int MAX_QUEUED = 200_000;

    private final SenderConnection connection;
    private final EventCache cache;
    private final ArrayDeque<CachedEvent> queue = new ArrayDeque<>();
    private final Set<Integer> nodes = new HashSet<>();
    private final Thread pusher;
    private boolean overflow;
    private volatile boolean closed;

    MonitorStream(SenderConnection connection, EventCache cache) {
        this.connection = connection;
        this.cache = cache;
        this.pusher = new Thread(this::push, "fdnet-monitor-" + connection.describe());
        pusher.setDaemon(true);
        pusher.start();
    }

    @Override
    public void offer(CachedEvent event) {
        synchronized (queue) {
            if (queue.size() >= MAX_QUEUED || overflow) {
                overflow = true;
                cache.delivered(List.of(event)); // never sent: it must not wait for this viewer
            } else {
                queue.addLast(event);
            }
            queue.notifyAll();
        }
    }

    void monitor(int[] ids) {
        synchronized (nodes) {
            for (int id : ids) {
                nodes.add(id);
            }
        }
        cache.subscribe(this, ids);
    }

    void unmonitor(int[] ids) {
        int[] which = ids;
        synchronized (nodes) {
            if (which.length == 0) {
                which = nodes.stream().mapToInt(Integer::intValue).toArray();
            }
            for (int id : which) {
                nodes.remove(id);
            }
        }
        Set<Integer> gone = new HashSet<>();
        for (int id : which) {
            gone.add(id);
        }
        List<CachedEvent> dropped = new ArrayList<>();
        synchronized (queue) {
            queue.removeIf(e -> {
                if (gone.contains(e.sourceId())) {
                    dropped.add(e);
                    return true;
                }
                return false;
            });
        }
        cache.unsubscribe(this, which, dropped);
    }

    void close() {
        closed = true;
        unmonitor(new int[0]);
        synchronized (queue) {
            queue.notifyAll();
        }
    }

    private void push() {
        List<CachedEvent> batch = new ArrayList<>(Protocol.MAX_EVENTS_PER_FRAME);
        try {
            while (!closed) {
                synchronized (queue) {
                    while (queue.isEmpty() && !overflow && !closed) {
                        queue.wait(500);
                    }
                    if (overflow) {
                        break;
                    }
                    while (batch.size() < Protocol.MAX_EVENTS_PER_FRAME && !queue.isEmpty()) {
                        batch.add(queue.pollFirst());
                    }
                }
                if (batch.isEmpty()) {
                    continue;
                }
                try {
                    connection.sendMonitored(batch);
                } finally {
                    cache.delivered(batch);
                    batch.clear();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException e) {
            LOG.debug("monitor stream of {} ended: {}", connection.describe(), e.getMessage());
        }
        if (overflow) {
            LOG.warn("disconnecting viewer {}: more than {} monitored events waiting", connection.describe(), MAX_QUEUED);
            connection.refuse(ErrorCode.BAD_REQUEST, "viewer too slow: more than " + MAX_QUEUED + " monitored events waiting");
        }
        close();
    }
}
