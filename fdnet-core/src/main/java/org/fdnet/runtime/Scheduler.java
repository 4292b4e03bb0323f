package org.fdnet.runtime;

import java.util.ArrayDeque;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs ready Relations: on the thread that made them ready when it can (run-to-completion: no handoff,
 * a hop costs a few hundred nanoseconds), on a bounded pool of workers otherwise — when the caller is
 * the period timer, when the caller may not run them (inline runs switched off), when a drain used its
 * budget (so a feedback loop cannot keep one thread forever), and when there is more ready work than
 * one thread and a worker is idle (parallelism).
 *
 * <pre>
 *   dispatch(r) ─┬─ this thread is draining ──▶ its local queue (runs after the current firing)
 *                ├─ caller may run inline ────▶ local queue, drain now
 *                └─ else ─────────────────────▶ pool queue ──▶ worker drains it the same way
 * </pre>
 */
final class Scheduler implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(Scheduler.class);
    private static final int LOCAL_CAPACITY = 4096;

    private final Dataflow flow;
    private final LinkedBlockingQueue<RelationNode> pool = new LinkedBlockingQueue<>();
    private final Thread[] workers;
    private final AtomicInteger idle = new AtomicInteger();
    private final ThreadLocal<LocalRun> local = ThreadLocal.withInitial(LocalRun::new);
    private final int budget;
    private final boolean inlineCallers;
    private volatile boolean running = true;

    private static final class LocalRun {
        final ArrayDeque<RelationNode> queue = new ArrayDeque<>();
        boolean draining;
    }

    Scheduler(Dataflow flow, int threads, int budget, boolean inlineCallers) {
        this.flow = flow;
        this.budget = budget;
        this.inlineCallers = inlineCallers;
        this.workers = new Thread[threads];
        for (int i = 0; i < threads; i++) {
            Thread t = new Thread(this::work, "fdnet-worker-" + i);
            t.setDaemon(true);
            workers[i] = t;
        }
        for (Thread t : workers) {
            t.start();
        }
    }

    void dispatch(RelationNode r) {
        LocalRun l = local.get();
        if (l.draining) {
            if (l.queue.size() < LOCAL_CAPACITY) {
                l.queue.add(r);
            } else {
                pool.add(r);
            }
        } else if (inlineCallers && running) {
            l.queue.add(r);
            drain(l);
        } else {
            pool.add(r);
        }
    }

    void submit(RelationNode r) {
        pool.add(r);
    }

    private void drain(LocalRun l) {
        l.draining = true;
        int left = budget;
        try {
            RelationNode r;
            while ((r = l.queue.poll()) != null) {
                if (--left < 0) {
                    pool.add(r);
                    break;
                }
                if (!l.queue.isEmpty() && idle.get() > 0) {
                    pool.add(l.queue.pollLast());
                }
                r.runAndSettle(flow);
            }
        } finally {
            RelationNode rest;
            while ((rest = l.queue.poll()) != null) {
                pool.add(rest);
            }
            l.draining = false;
        }
    }

    private void work() {
        LocalRun l = local.get();
        idle.incrementAndGet();
        while (running) {
            RelationNode r;
            try {
                r = pool.poll(50, TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                break;
            }
            if (r == null) {
                continue;
            }
            idle.decrementAndGet();
            try {
                l.queue.add(r);
                drain(l);
            } catch (RuntimeException | Error e) {
                LOG.error("worker {} hit an engine error; it keeps working", Thread.currentThread().getName(), e);
            } finally {
                idle.incrementAndGet();
            }
        }
    }

    /**
     * Runs everything queued for the pool on the calling thread until nothing is left: a driven network's
     * pool (it has no workers). Returns the number of Relations taken from the pool.
     */
    int runQueuedHere() {
        LocalRun l = local.get();
        int taken = 0;
        RelationNode r;
        while ((r = pool.poll()) != null) {
            taken++;
            l.queue.add(r);
            drain(l);
        }
        return taken;
    }

    int threads() {
        return workers.length;
    }

    @Override
    public void close() {
        running = false;
        for (Thread t : workers) {
            t.interrupt();
        }
        for (Thread t : workers) {
            try {
                t.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }
}
