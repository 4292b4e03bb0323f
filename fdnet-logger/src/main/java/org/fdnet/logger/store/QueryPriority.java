package org.fdnet.logger.store;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * Viewer queries before bulk work. While a viewer's query is being answered, the writer's COPY (and the
 * PostgreSQL backend it feeds: a backend with no rows to read sleeps) and the receivers pause at their next
 * chunk boundary, so the few cores serve the query; they resume when the last query ends.
 *
 * <pre>
 *   sender: begin() ── answer from cache/database ── end() ─signal─┐
 *   writer lane: rows chunk ─COPY─ yieldToQueries() ◀──────────────┘  (waits while answering &gt; 0, bounded)
 *   receiver: frame ─ yieldToQueries() ─ frame ...
 * </pre>
 *
 * Bounded so that bulk work never starves: one {@link #yieldToQueries} waits at most {@code maxPauseNanos},
 * and a caller does a chunk of work between two yields. When nobody queries, a yield is one volatile read.
 */
public final class QueryPriority {
    private volatile long maxPauseNanos;
    private final AtomicInteger answering = new AtomicInteger();
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition idle = lock.newCondition();

    /** @param maxPauseMillis the longest one yield waits (0: never wait) */
    public QueryPriority(long maxPauseMillis) {
        maxPauseMillis(maxPauseMillis);
    }

    /**
     * Changes the longest pause while running (the one setting of this class that may change: a benchmark
     * compares pausing with not pausing in one run).
     */
    public void maxPauseMillis(long millis) {
        if (millis < 0) {
            throw new IllegalArgumentException("maxPauseMillis must be at least 0, was " + millis);
        }
        maxPauseNanos = TimeUnit.MILLISECONDS.toNanos(millis);
    }

    /** A query starts being answered. Pair with {@link #end()} in a finally block. */
    public void begin() {
        answering.incrementAndGet();
    }

    /** A query's answer is sent. */
    public void end() {
        if (answering.decrementAndGet() == 0) {
            lock.lock();
            try {
                idle.signalAll();
            } finally {
                lock.unlock();
            }
        }
    }

    /** Whether a query is being answered now. */
    public boolean queried() {
        return answering.get() > 0;
    }

    /**
     * Waits while a query is being answered, at most the pause this was made with. Returns at once when none
     * is; keeps the interrupt status if interrupted.
     */
    public void yieldToQueries() {
        long pause = maxPauseNanos;
        if (answering.get() == 0 || pause == 0) {
            return;
        }
        lock.lock();
        try {
            long left = pause;
            while (answering.get() > 0 && left > 0) {
                left = idle.awaitNanos(left);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            lock.unlock();
        }
    }
}
