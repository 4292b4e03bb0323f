package org.fdnet.runtime.engine;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
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
 *
 * The pool can be {@linkplain #resize resized} while it runs (a host's engine serves each network deployed there in
 * turn, each run with its own worker count): new workers start at once; a retired worker finishes the drain it is
 * in and stops within one poll of the pool queue.
 */
final class Scheduler implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(Scheduler.class);
    private static final int LOCAL_CAPACITY = 4096;

    private final Dataflow flow;
    private final LinkedBlockingQueue<RelationNode> pool = new LinkedBlockingQueue<>();
    private final List<Worker> workers = new ArrayList<>(); // guarded by this
    private int workersStarted; // guarded by this: numbers the workers' threads
    private final boolean driven;
    private final AtomicInteger idle = new AtomicInteger();
    private final ThreadLocal<LocalRun> local = ThreadLocal.withInitial(LocalRun::new);
    private final int budget;
    private final boolean inlineCallers;
    private final Runnable workerStart;
    private volatile boolean running = true;

    /** One worker thread; {@code retired} asks it to stop after the drain it is in. */
    private static final class Worker {
        Thread thread;
        volatile boolean retired;
    }

    private static final class LocalRun {
        final ArrayDeque<RelationNode> queue = new ArrayDeque<>();
        boolean draining;
    }

    Scheduler(Dataflow flow, int threads, int budget, boolean inlineCallers, Runnable workerStart) {
        this.flow = flow;
        this.budget = budget;
        this.inlineCallers = inlineCallers;
        this.workerStart = workerStart;
        this.driven = threads == 0;
        if (!driven) {
            resize(threads);
        }
    }

    /**
     * Runs {@code threads} workers from now on: starts the missing ones, retires the extra ones.
     *
     * @throws IllegalArgumentException when {@code threads} is below 1
     * @throws IllegalStateException for a driven network's pool, which has no workers
     */
    synchronized void resize(int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException("worker threads must be at least 1, was " + threads);
        }
        if (driven) {
            throw new IllegalStateException("a network on a driven clock runs every firing on its driver's thread;"
                    + " it has no worker threads to size");
        }
        while (running && workers.size() < threads) {
            Worker w = new Worker();
            w.thread = new Thread(() -> work(w), "fdnet-worker-" + workersStarted++);
            w.thread.setDaemon(true);
            workers.add(w);
            w.thread.start();
        }
        while (workers.size() > threads) {
            workers.remove(workers.size() - 1).retired = true;
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

    private void work(Worker self) {
        try {
            workerStart.run();
        } catch (RuntimeException e) {
            LOG.warn("worker {}: its start action failed; it works on without it", Thread.currentThread().getName(), e);
        }
        LocalRun l = local.get();
        idle.incrementAndGet();
        while (running && !self.retired) {
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
        idle.decrementAndGet();
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

    synchronized int threads() {
        return workers.size();
    }

    @Override
    public void close() {
        List<Thread> threads;
        synchronized (this) {
            running = false;
            threads = workers.stream().map(w -> w.thread).toList();
        }
        for (Thread t : threads) {
            t.interrupt();
        }
        for (Thread t : threads) {
            try {
                t.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }
}
