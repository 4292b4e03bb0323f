package org.fdnet.logger.cache;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.event.TypedValue;

/**
 * The logger's cache (thesis, chapter 4 IV): two event containers — network state (Data and Relation
 * values, with monitoring) and network commands — each indexed by node id, then time; plus the queue of
 * events not yet written, in arrival order, which the writer drains. Node names travel through the queue
 * only (the store keeps them).
 *
 * <pre>
 *   receiver ─add()─▶ unwritten queue ──takeBatch()──▶ writer ──COPY, commit──▶ committed()
 *                │                                                                │
 *                └─▶ states (MonitoredEventContainer) ─offer─▶ monitors          evict: committed
 *                └─▶ commands (EventContainer)                                   and not monitored
 *   viewer ─history()─▶ both containers (node, then time)
 * </pre>
 *
 * <p>Memory: every event counts its configured size plus its value's length. At the critical level the
 * cache is "pressured": {@link #awaitRoom} holds the receivers back (TCP flow control does the rest) and
 * the writer runs at full rate, until the level falls to normal. {@link #add} never goes beyond the
 * capacity. One lock guards the byte accounting, the unwritten queue, the monitors and every change to the
 * containers (the thesis's integrity concern); each call holds it briefly. {@link #history} does not take it:
 * it reads the node's timelines under their own locks (see {@link NodeTimeline}), so a viewer's query never
 * waits behind the writer's per-batch work or a receiver's batch.
 */
public final class EventCache {
    private final CacheLimits limits;
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition room = lock.newCondition();
    private final Condition arrived = lock.newCondition();
    private final MonitoredEventContainer states = new MonitoredEventContainer();
    private final EventContainer commands = new EventContainer();
    private final ArrayDeque<CachedEvent> unwritten = new ArrayDeque<>();
    private long usedBytes;
    private volatile boolean pressured;
    private volatile long received;
    private volatile long committed;

    public EventCache(CacheLimits limits) {
        this.limits = limits;
    }

    public CacheLimits limits() {
        return limits;
    }

    /** The bytes an event counts for. */
    public int sizeOf(NetworkEvent e) {
        if (e instanceof DataValueEvent d) {
            return limits.networkEventBytes() + payloadBytes(d.value());
        } else if (e instanceof RelationValueEvent r) {
            return limits.networkEventBytes() + r.value().length();
        } else if (e instanceof NetworkCommandEvent c) {
            return limits.commandEventBytes() + c.paramsId().length();
        }
        NodeNamedEvent n = (NodeNamedEvent) e;
        return limits.networkEventBytes() + n.name().module().length() + n.name().node().length();
    }

    /** A value's payload as the wire carries it: 1 byte for a boolean, 8 for a number, a string's length, 8 per element. */
    private static int payloadBytes(TypedValue v) {
        return switch (v.type()) {
            case BOOLEAN -> 1;
            case LONG, DOUBLE -> 8;
            case STRING -> v.stringValue().length();
            case BYTES -> v.length();
            case DOUBLES -> 8 * v.length();
        };
    }

    /** Blocks while the cache is pressured (critical level reached, normal not yet regained). */
    public void awaitRoom() throws InterruptedException {
        if (!pressured) {
            return;
        }
        lock.lock();
        try {
            while (pressured) {
                room.await(100, TimeUnit.MILLISECONDS);
            }
        } finally {
            lock.unlock();
        }
    }

    /** Takes events in; waits rather than go beyond the capacity (an empty cache takes anything). */
    public void add(List<CachedEvent> batch) throws InterruptedException {
        long bytes = 0;
        for (CachedEvent e : batch) {
            bytes += e.bytes();
        }
        lock.lock();
        try {
            while (usedBytes > 0 && usedBytes + bytes > limits.capacityBytes()) {
                room.await(100, TimeUnit.MILLISECONDS);
            }
            for (CachedEvent e : batch) {
                NetworkEvent ev = e.event();
                if (ev instanceof DataValueEvent || ev instanceof RelationValueEvent) {
                    states.add(e);
                } else if (ev instanceof NetworkCommandEvent) {
                    commands.add(e);
                }
                unwritten.addLast(e);
            }
            usedBytes += bytes;
            received += batch.size();
            if (usedBytes >= limits.criticalBytes()) {
                pressured = true;
            }
            arrived.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** Wakes a writer waiting in {@link #awaitUnwritten} (a flush was asked for). */
    public void wake() {
        lock.lock();
        try {
            arrived.signalAll();
        } finally {
            lock.unlock();
        }
    }

    public boolean pressured() {
        return pressured;
    }

    /**
     * Waits up to {@code maxWaitNanos} for at least {@code want} unwritten events older than
     * {@code minAgeNanos} and returns how many there are (possibly fewer: the caller decides by its timer).
     */
    public int awaitUnwritten(int want, long minAgeNanos, long maxWaitNanos) throws InterruptedException {
        long deadline = System.nanoTime() + maxWaitNanos;
        lock.lock();
        try {
            while (true) {
                int ready = readyCount(want, minAgeNanos);
                long left = deadline - System.nanoTime();
                if (ready >= want || left <= 0) {
                    return ready;
                }
                arrived.awaitNanos(Math.min(left, TimeUnit.MILLISECONDS.toNanos(50)));
            }
        } finally {
            lock.unlock();
        }
    }

    /** How many unwritten events (at most {@code max}) are older than {@code minAgeNanos}, without waiting. */
    public int readyUnwritten(int max, long minAgeNanos) {
        lock.lock();
        try {
            return readyCount(max, minAgeNanos);
        } finally {
            lock.unlock();
        }
    }

    private int readyCount(int want, long minAgeNanos) {
        if (minAgeNanos <= 0) {
            return Math.min(want, unwritten.size());
        }
        long newest = System.nanoTime() - minAgeNanos;
        int n = 0;
        for (CachedEvent e : unwritten) {
            if (n >= want || e.arrivalNanos() > newest) {
                break;
            }
            n++;
        }
        return n;
    }

    /**
     * The oldest unwritten events, at most {@code max}, in arrival order. They stay indexed (viewers still see
     * them) until {@link #committed}; if the write fails the writer retries the same batch.
     */
    public List<CachedEvent> takeBatch(int max) {
        return takeBatch(max, Long.MAX_VALUE);
    }

    /** As {@link #takeBatch(int)}, and at most {@code maxBytes} counted bytes (but always one event at least). */
    public List<CachedEvent> takeBatch(int max, long maxBytes) {
        lock.lock();
        try {
            List<CachedEvent> batch = new ArrayList<>(Math.min(max, unwritten.size()));
            long bytes = 0;
            while (batch.size() < max && !unwritten.isEmpty()) {
                CachedEvent next = unwritten.peekFirst();
                if (!batch.isEmpty() && bytes + next.bytes() > maxBytes) {
                    break;
                }
                bytes += next.bytes();
                batch.add(unwritten.pollFirst());
            }
            return batch;
        } finally {
            lock.unlock();
        }
    }

    /** The batch is in the database: mark it, let what is no longer monitored go, release the receivers. */
    public void committed(List<CachedEvent> batch) {
        lock.lock();
        try {
            for (CachedEvent e : batch) {
                e.markCommitted();
            }
            long freed = 0;
            for (CachedEvent e : batch) {
                if (e.left()) {
                    continue; // already evicted with an earlier event of its node: one eviction pass per node
                }
                NetworkEvent ev = e.event();
                if (ev instanceof NetworkCommandEvent) {
                    freed += commands.evict(e.sourceId());
                } else if (ev instanceof NodeNamedEvent) {
                    freed += e.bytes();
                } else {
                    freed += states.evict(e.sourceId());
                }
            }
            committed += batch.size();
            release(freed);
        } finally {
            lock.unlock();
        }
    }

    private void release(long freed) {
        usedBytes -= freed;
        if (pressured && usedBytes <= limits.normalBytes()) {
            pressured = false;
        }
        room.signalAll();
    }

    public void subscribe(MonitorSubscriber subscriber, int[] sourceIds) {
        lock.lock();
        try {
            for (int id : sourceIds) {
                states.subscribe(subscriber, id);
            }
        } finally {
            lock.unlock();
        }
    }

    /**
     * Stops monitoring; {@code undelivered} are the events the subscriber still held for those nodes, which
     * no longer wait for it.
     */
    public void unsubscribe(MonitorSubscriber subscriber, int[] sourceIds, List<CachedEvent> undelivered) {
        lock.lock();
        try {
            for (int id : sourceIds) {
                states.unsubscribe(subscriber, id);
            }
            deliveredLocked(undelivered);
        } finally {
            lock.unlock();
        }
    }

    /** A subscriber sent these events. */
    public void delivered(List<CachedEvent> sent) {
        lock.lock();
        try {
            deliveredLocked(sent);
        } finally {
            lock.unlock();
        }
    }

    private void deliveredLocked(List<CachedEvent> sent) {
        long freed = 0;
        for (CachedEvent e : sent) {
            freed += states.delivered(e);
        }
        if (freed > 0) {
            release(freed);
        }
    }

    /**
     * The node's events in {@code [from, to]} from both containers, in time order, and whether the cache
     * alone holds every such event (nothing of the node at or after {@code from} has left memory) — then
     * the database need not be asked. {@code complete} must be false for nodes this logger did not see
     * from their first event (e.g. a run resumed after a restart).
     */
    public CacheAnswer history(int sourceId, long from, long to, boolean sourceSeenFromStart) {
        CachedAnswer cached = cachedHistory(sourceId, from, to, sourceSeenFromStart);
        List<NetworkEvent> out = new ArrayList<>(cached.events().size());
        for (CachedEvent e : cached.events()) {
            out.add(e.event());
        }
        return new CacheAnswer(out, cached.complete());
    }

    /** Events of a node in a range, and whether they are all there are. */
    public record CacheAnswer(List<NetworkEvent> events, boolean complete) {
    }

    /**
     * As {@link #history}, the cached events themselves (their wire bytes kept for the next viewer): what a
     * sender answers from when {@code complete}.
     */
    public CachedAnswer cachedHistory(int sourceId, long from, long to, boolean sourceSeenFromStart) {
        // No cache lock: each container's timeline of this node is read under its own small lock, so the
        // query waits at most for work on this one node, never for the writer's batch or the receivers.
        ArrayList<CachedEvent> out = new ArrayList<>(0);
        long statesEvicted = states.range(sourceId, from, to, out);
        int stateCount = out.size();
        long commandsEvicted = commands.range(sourceId, from, to, out);
        if (stateCount > 0 && out.size() > stateCount) {
            out.sort(Comparator.comparingLong(CachedEvent::time));
        }
        boolean covered = sourceSeenFromStart && statesEvicted < from && commandsEvicted < from;
        return new CachedAnswer(out, covered);
    }

    /** Cached events of a node in a range, and whether they are all there are. */
    public record CachedAnswer(List<CachedEvent> events, boolean complete) {
    }

    /**
     * Every event of one node the cache holds now, monitored or not, written or not, in time order (the
     * panel's cache browser).
     */
    public List<CacheEntry> entriesOf(int sourceId) {
        List<CachedEvent> held = cachedHistory(sourceId, Long.MIN_VALUE, Long.MAX_VALUE, false).events();
        List<CacheEntry> out = new ArrayList<>(held.size());
        lock.lock(); // committed and pendingMonitors are guarded by the cache's lock
        try {
            for (CachedEvent e : held) {
                out.add(new CacheEntry(e.event(), e.committed(), e.pendingMonitors > 0));
            }
        } finally {
            lock.unlock();
        }
        return out;
    }

    public CacheStatus status() {
        lock.lock();
        try {
            CachedEvent oldest = unwritten.peekFirst();
            long lag = oldest == null ? 0 : TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - oldest.arrivalNanos());
            return new CacheStatus(usedBytes, limits.capacityBytes(), states.size() + commands.size(), unwritten.size(),
                    states.monitoredEvents(), received, committed, pressured, lag, states.monitorCount());
        } finally {
            lock.unlock();
        }
    }

    public int unwrittenCount() {
        lock.lock();
        try {
            return unwritten.size();
        } finally {
            lock.unlock();
        }
    }

    public long received() {
        return received;
    }

    public long committedCount() {
        return committed;
    }
}
