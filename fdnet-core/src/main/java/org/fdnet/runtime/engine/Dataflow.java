package org.fdnet.runtime.engine;

import java.time.Instant;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.LongAdder;
import java.util.concurrent.locks.StampedLock;
import java.util.function.Function;
import org.fdnet.runtime.Servants;
import org.fdnet.runtime.Value;

/**
 * The hot path: snapshots, commits and run requests. Values move like this:
 *
 * <pre>
 *   writer (Relation firing / setValue / sensor push)
 *     │ convert + Data.accept        (outside any lock)
 *     ▼
 *   commit lock (write) ── stamp time ── store ── observers ── DataValueEvent
 *     │ unlock
 *     ▼
 *   each reader (not the writer itself) ── request() ── Scheduler.dispatch
 * </pre>
 *
 * One {@link StampedLock} makes a firing's writes visible together and a reader's snapshot consistent:
 * readers validate an optimistic read and only take the read lock when a commit raced them.
 */
final class Dataflow {
    private final StampedLock commitLock = new StampedLock();
    /** The thread inside a commit: an observer that writes back would wait on itself forever (the lock is not reentrant). */
    private volatile Thread committer;
    private final EventPublisher events;
    private Scheduler scheduler;
    private final AtomicInteger busy = new AtomicInteger();
    private final LongAdder firings = new LongAdder();
    private final LongAdder writes = new LongAdder();
    private final long startNanos = System.nanoTime();
    /** Simulated time, or {@code null} on the wall clock. */
    private final DrivenClock driven;
    private final long drivenStartMicros;
    private volatile Function<RelationNode, Servants> servants = r -> {
        throw new IllegalStateException("no servants in this network");
    };

    Dataflow(EventPublisher events, DrivenClock driven) {
        this.events = events;
        this.driven = driven;
        this.drivenStartMicros = driven == null ? 0 : driven.micros();
    }

    void attach(Scheduler s) {
        this.scheduler = s;
    }

    void servants(Function<RelationNode, Servants> factory) {
        this.servants = factory;
    }

    Scheduler scheduler() {
        return scheduler;
    }

    EventPublisher events() {
        return events;
    }

    Servants servantsFor(RelationNode node) {
        return servants.apply(node);
    }

    /** Fills {@code into} with the inputs' current values, all from between the same two commits. */
    void snapshot(DataNode[] inputs, Value[] into) {
        if (inputs.length <= 1) {
            if (inputs.length == 1) {
                into[0] = inputs[0] == null ? null : inputs[0].value;
            }
            return;
        }
        long stamp = commitLock.tryOptimisticRead();
        read(inputs, into);
        if (!commitLock.validate(stamp)) {
            stamp = commitLock.readLock();
            try {
                read(inputs, into);
            } finally {
                commitLock.unlockRead(stamp);
            }
        }
    }

    private static void read(DataNode[] inputs, Value[] into) {
        for (int i = 0; i < inputs.length; i++) {
            DataNode d = inputs[i];
            into[i] = d == null ? null : d.value;
        }
    }

    /**
     * Publishes one firing's outputs together and tells their readers. {@code values[i]} may be null
     * (not written); the array is cleared for the next firing. Throws (writing nothing) when a value
     * does not fit its Data.
     */
    void commit(RelationNode writer, DataNode[] outputs, Value[] values) {
        boolean any = false;
        try {
            for (int i = 0; i < values.length; i++) {
                if (values[i] != null) {
                    if (outputs[i] == null) {
                        values[i] = null;
                    } else {
                        values[i] = outputs[i].prepare(values[i]);
                        any = true;
                    }
                }
            }
            if (!any) {
                return;
            }
            long stamp = lockForWrite();
            try {
                for (int i = 0; i < values.length; i++) {
                    if (values[i] != null) {
                        if (outputs[i].alive) {
                            store(outputs[i], values[i]);
                        } else {
                            values[i] = null;
                        }
                    }
                }
            } finally {
                unlockWrite(stamp);
            }
            for (int i = 0; i < values.length; i++) {
                if (values[i] != null) {
                    notifyReaders(outputs[i], writer);
                }
            }
        } finally {
            java.util.Arrays.fill(values, null);
        }
    }

    /** One value from outside a firing (controller, sensor) or from a writer of a single Data. */
    void write(DataNode data, Value value, RelationNode writer) {
        Value prepared = data.prepare(value);
        long stamp = lockForWrite();
        try {
            if (!data.alive) {
                return;
            }
            store(data, prepared);
        } finally {
            unlockWrite(stamp);
        }
        notifyReaders(data, writer);
    }

    /** A new Data's first value: stamped and logged, but nobody is told (its readers fire when wired). */
    void initialize(DataNode data, Value first) {
        long stamp = lockForWrite();
        try {
            store(data, first);
        } finally {
            unlockWrite(stamp);
        }
    }

    private long lockForWrite() {
        if (committer == Thread.currentThread()) {
            throw new IllegalStateException("a value observer or event sink wrote to the network while a commit was"
                    + " telling it of a value; observers and sinks must enqueue and return");
        }
        long stamp = commitLock.writeLock();
        committer = Thread.currentThread();
        return stamp;
    }

    private void unlockWrite(long stamp) {
        committer = null;
        commitLock.unlockWrite(stamp);
    }

    private void store(DataNode data, Value prepared) {
        Value stamped = prepared.at(events.clock().next());
        data.store(stamped);
        if (!data.standIn) {
            // a stand-in's values are the remote Data's: its own host logs them
            events.dataValue(data, stamped);
        }
        writes.increment();
    }

    private void notifyReaders(DataNode data, RelationNode writer) {
        for (RelationNode r : data.readers) {
            if (r != writer) {
                request(r);
            }
        }
    }

    /** Asks a Relation to run; dispatches it if it was idle. */
    void request(RelationNode r) {
        if (r.request()) {
            busy.incrementAndGet();
            scheduler.dispatch(r);
        }
    }

    /** Like {@link #request} but never on the caller's thread: for the period timer. */
    void requestOnPool(RelationNode r) {
        if (r.request()) {
            busy.incrementAndGet();
            scheduler.submit(r);
        }
    }

    void settled() {
        busy.decrementAndGet();
    }

    void countFiring() {
        firings.increment();
    }

    long firings() {
        return firings.sum();
    }

    long writes() {
        return writes.sum();
    }

    void reportState(RelationNode r) {
        events.relationValue(r.id, r.state().text());
    }

    /** Waits until no Relation is queued or running (periodic ones may start again at once). */
    boolean awaitQuiet(long timeout, TimeUnit unit) throws InterruptedException {
        long deadline = System.nanoTime() + unit.toNanos(timeout);
        while (busy.get() != 0) {
            if (System.nanoTime() > deadline) {
                return false;
            }
            Thread.sleep(1);
        }
        return true;
    }

    /** Time now, µs since the epoch: the wall's, or the driven clock's. */
    long wallMicros() {
        if (driven != null) {
            return driven.micros();
        }
        Instant now = Instant.now();
        return now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000L;
    }

    double secondsSinceStart() {
        if (driven != null) {
            return (driven.micros() - drivenStartMicros) / 1e6;
        }
        return (System.nanoTime() - startNanos) / 1e9;
    }
}
