package org.fdnet.runtime.engine;

import java.util.ArrayList;
import java.util.List;
import org.fdnet.event.EventClock;
import org.fdnet.event.EventSink;
import org.fdnet.runtime.Placement;
import org.fdnet.runtime.loading.ClassLoadingPolicy;

/**
 * How a network runs: every setting in one place, checked when set, fixed once the network starts.
 * Defaults suit {@code fdnet run}: every node local, one worker per core, inline runs on.
 */
public final class RuntimeOptions {
    private Placement placement = Placement.all();
    private int workerThreads = Math.max(1, Runtime.getRuntime().availableProcessors());
    private int drainBudget = 256;
    private boolean inlineCallers = true;
    private Runnable workerStart = () -> { };
    private ClassLoadingPolicy classLoading = ClassLoadingPolicy.builtInOnly();
    private EventClock clock = new EventClock();
    private DrivenClock driven;
    private final List<EventSink> sinks = new ArrayList<>();
    private volatile boolean sealed;

    public static RuntimeOptions defaults() {
        return new RuntimeOptions();
    }

    /** Which nodes this process runs (the distribution seam). Default: all. */
    public RuntimeOptions placement(Placement p) {
        checkOpen();
        this.placement = java.util.Objects.requireNonNull(p, "placement");
        return this;
    }

    /** Size of the worker pool (the bound on Relations computing in parallel off callers' threads). */
    public RuntimeOptions workerThreads(int threads) {
        checkOpen();
        if (threads < 1) {
            throw new IllegalArgumentException("workerThreads must be at least 1, was " + threads);
        }
        this.workerThreads = threads;
        return this;
    }

    /** Firings one thread runs in a row before it hands the rest to the pool (fairness in feedback loops). */
    public RuntimeOptions drainBudget(int firings) {
        checkOpen();
        if (firings < 1) {
            throw new IllegalArgumentException("drainBudget must be at least 1, was " + firings);
        }
        this.drainBudget = firings;
        return this;
    }

    /**
     * Whether a thread that writes a Data from outside a firing (setValue, a sensor push) runs the Relations
     * it made ready itself, up to the drain budget (fast), or leaves them all to the pool (caller returns at once).
     */
    public RuntimeOptions inlineCallers(boolean inline) {
        checkOpen();
        this.inlineCallers = inline;
        return this;
    }

    /**
     * Runs first on each worker thread the network starts: e.g. a real-time scheduling class for the workers of a
     * network that answers a robot's sensors (a loaded machine's other processes took a worker's core for 7-13 ms in
     * the middle of a tilt reflex's answer). It must return; what it throws is logged and the worker works on.
     */
    public RuntimeOptions workerStart(Runnable action) {
        checkOpen();
        this.workerStart = java.util.Objects.requireNonNull(action, "workerStart");
        return this;
    }

    public RuntimeOptions classLoading(ClassLoadingPolicy policy) {
        checkOpen();
        this.classLoading = java.util.Objects.requireNonNull(policy, "classLoading");
        return this;
    }

    /** The clock stamping this network's events (share one per process). */
    public RuntimeOptions clock(EventClock c) {
        checkOpen();
        this.clock = java.util.Objects.requireNonNull(c, "clock");
        return this;
    }

    /**
     * Runs the network on simulated time instead of the wall clock: no timer or worker threads; the driver
     * calls {@link RuntimeNetwork#advanceTo} and every firing runs on its thread. Events are stamped from
     * this clock (it replaces any {@link #clock(EventClock)}).
     */
    public RuntimeOptions drivenClock(DrivenClock c) {
        checkOpen();
        this.driven = java.util.Objects.requireNonNull(c, "drivenClock");
        this.clock = new EventClock(c::micros);
        return this;
    }

    public RuntimeOptions sink(EventSink sink) {
        checkOpen();
        sinks.add(java.util.Objects.requireNonNull(sink, "sink"));
        return this;
    }

    /** Fixes the options: the network that starts with them reads them once. */
    void seal() {
        sealed = true;
    }

    private void checkOpen() {
        if (sealed) {
            throw new IllegalStateException("runtime options are fixed once a network starts with them; make new ones");
        }
    }

    Placement placement() {
        return placement;
    }

    int workerThreads() {
        return workerThreads;
    }

    int drainBudget() {
        return drainBudget;
    }

    boolean inlineCallers() {
        return inlineCallers;
    }

    Runnable workerStart() {
        return workerStart;
    }

    ClassLoadingPolicy classLoading() {
        return classLoading;
    }

    EventClock clock() {
        return clock;
    }

    /** The driven clock, or {@code null} on the wall clock. */
    DrivenClock drivenClock() {
        return driven;
    }

    List<EventSink> sinks() {
        return List.copyOf(sinks);
    }
}
