package org.fdnet.roq.sim;

import java.nio.ByteBuffer;

import static org.fdnet.roq.sim.SharedBlockLayout.*;

/**
 * The joint loop's counters, refilled in place by {@link RoqSimulator#statistics(LoopStatistics)}. Wake-up latency
 * (how late the loop's thread woke after its absolute deadline) is kept in 1 µs bins up to 2 ms; it is only
 * measured in {@link SimMode#REAL_TIME}. An overrun is a tick whose work ended after the next tick's deadline.
 */
public final class LoopStatistics {
    private long ticks;
    private long overruns;
    private long maxOverrunNanos;
    private long maxLatencyNanos;
    private long latencySamples;
    private long commandsApplied;
    private long commandsNan;
    private long commandsOutOfRange;
    private long commandsStale;
    private long realtimeFlags;
    private long maxTickNanos;
    private final int[] histogram = new int[HISTOGRAM_BINS];
    private long lastAppliedTick;
    private long lastAppliedBasedOn;
    private final int[] reflex = new int[REFLEX_BINS];

    void copyFrom(ByteBuffer b) {
        ticks = b.getLong(T_TICKS);
        overruns = b.getLong(T_OVERRUNS);
        maxOverrunNanos = b.getLong(T_MAX_OVERRUN_NS);
        maxLatencyNanos = b.getLong(T_MAX_LATENCY_NS);
        latencySamples = b.getLong(T_LATENCY_SAMPLES);
        commandsApplied = b.getLong(T_COMMANDS_APPLIED);
        commandsNan = b.getLong(T_COMMANDS_NAN);
        commandsOutOfRange = b.getLong(T_COMMANDS_OUT_OF_RANGE);
        commandsStale = b.getLong(T_COMMANDS_STALE);
        realtimeFlags = b.getLong(T_RT_FLAGS);
        maxTickNanos = b.getLong(T_MAX_TICK_NS);
        for (int i = 0; i < HISTOGRAM_BINS; i++) {
            histogram[i] = b.getInt(T_HISTOGRAM + 4 * i);
        }
        lastAppliedTick = b.getLong(T_LAST_APPLIED_TICK);
        lastAppliedBasedOn = b.getLong(T_LAST_APPLIED_BASED_ON);
        for (int i = 0; i < REFLEX_BINS; i++) {
            reflex[i] = b.getInt(T_REFLEX_HISTOGRAM + 4 * i);
        }
    }

    /** Ticks run since the simulator opened. */
    public long ticks() {
        return ticks;
    }

    /** Ticks whose work ended after the next deadline. */
    public long overruns() {
        return overruns;
    }

    /** The worst overrun: how far past the next deadline a tick ended, ns. */
    public long maxOverrunNanos() {
        return maxOverrunNanos;
    }

    /** The worst wake-up latency, ns. */
    public long maxLatencyNanos() {
        return maxLatencyNanos;
    }

    /** The longest tick's work (wake-up to end of publish), ns; measured in {@link SimMode#REAL_TIME} only. */
    public long maxTickNanos() {
        return maxTickNanos;
    }

    /** Wake-ups measured. */
    public long latencySamples() {
        return latencySamples;
    }

    /**
     * The wake-up latency below which {@code percentile} % of wake-ups fall, ns (upper edge of its 1 µs bin;
     * 0 with no samples; the histogram ends at 2 ms, see {@link #maxLatencyNanos()} for later ones).
     */
    public long latencyPercentileNanos(double percentile) {
        long total = 0;
        for (int c : histogram) {
            total += c;
        }
        if (total == 0) {
            return 0;
        }
        long rank = (long) Math.ceil(percentile / 100.0 * total);
        long seen = 0;
        for (int i = 0; i < HISTOGRAM_BINS; i++) {
            seen += histogram[i];
            if (seen >= rank) {
                return (i + 1) * 1000L;
            }
        }
        return HISTOGRAM_BINS * 1000L;
    }

    /** Wake-ups whose latency fell in 1 µs bin {@code bin} (0 ≤ bin < {@link SharedBlockLayout#HISTOGRAM_BINS}; the
     * last bin also counts every later one). */
    public long latencyCount(int bin) {
        return histogram[bin];
    }

    /** Commands taken from the slot and applied (possibly clamped). */
    public long commandsApplied() {
        return commandsApplied;
    }

    /** NaN or infinite values ignored (each counts once). */
    public long commandsNan() {
        return commandsNan;
    }

    /** Targets or wheel speeds out of range, clamped (each counts once). */
    public long commandsOutOfRange() {
        return commandsOutOfRange;
    }

    /** Whole commands ignored because they were based on a snapshot too old. */
    public long commandsStale() {
        return commandsStale;
    }

    /** Bad values and commands of every kind. */
    public long badCommands() {
        return commandsNan + commandsOutOfRange + commandsStale;
    }

    /** Whether the loop's thread runs under SCHED_FIFO. */
    public boolean schedFifo() {
        return (realtimeFlags & RT_SCHED_FIFO) != 0;
    }

    /** Whether the process's memory is locked (mlockall). */
    public boolean memoryLocked() {
        return (realtimeFlags & RT_MLOCKALL) != 0;
    }

    /** Whether /dev/cpu_dma_latency is held at 0. */
    public boolean dmaLatencyHeld() {
        return (realtimeFlags & RT_DMA_LATENCY) != 0;
    }

    /** The tick counter when the loop applied the last command (0 before the first). */
    public long lastAppliedTick() {
        return lastAppliedTick;
    }

    /** The snapshot tick the last applied command was based on. */
    public long lastAppliedBasedOn() {
        return lastAppliedBasedOn;
    }

    /**
     * Commands applied whose reflex latency was {@code ticks} ticks (1 ms each): from the snapshot the command was
     * based on to the first snapshot computed under it; the last bin ({@link SharedBlockLayout#REFLEX_BINS} - 1)
     * also counts every later one.
     */
    public long reflexCount(int ticks) {
        return reflex[ticks];
    }

    /** The reflex latency below or at which {@code percentile} % of applied commands fall, ticks (0 with none). */
    public int reflexPercentileTicks(double percentile) {
        long total = 0;
        for (int c : reflex) {
            total += c;
        }
        if (total == 0) {
            return 0;
        }
        long rank = (long) Math.ceil(percentile / 100.0 * total);
        long seen = 0;
        for (int i = 0; i < REFLEX_BINS; i++) {
            seen += reflex[i];
            if (seen >= rank) {
                return i;
            }
        }
        return REFLEX_BINS - 1;
    }
}
