package org.fdnet.runtime;

/**
 * Simulated time for a network that a driver advances, instead of the wall clock: a stepped simulator
 * alternates {@code step(n)} of its plant with {@link RuntimeNetwork#advanceTo} of the network on one thread,
 * so a run is reproducible event by event. Time never goes backwards.
 *
 * <p>Times are microseconds since the epoch, as on the wall clock, so the logger stores them alike: simulated
 * time 0 is {@code originMicros}. Tests pass a fixed origin (two runs then log identical events); a demo passes
 * the wall time at its start. Read from any thread; only the network that runs on it moves it.
 */
public final class DrivenClock {
    private final long originMicros;
    private volatile long simMicros;

    /** @param originMicros the epoch microseconds that simulated time 0 maps to; not negative */
    public DrivenClock(long originMicros) {
        if (originMicros < 0) {
            throw new IllegalArgumentException("originMicros must not be negative, was " + originMicros);
        }
        this.originMicros = originMicros;
    }

    /** The current time, µs since the epoch: the origin plus the simulated time. */
    public long micros() {
        return originMicros + simMicros;
    }

    /** Simulated µs since the origin. */
    public long simMicros() {
        return simMicros;
    }

    /** Simulated seconds since the origin. */
    public double seconds() {
        return simMicros / 1e6;
    }

    public long originMicros() {
        return originMicros;
    }

    /** Moves the clock to {@code sim} µs after the origin; never back. */
    void moveTo(long sim) {
        if (sim < simMicros) {
            throw new IllegalArgumentException("a driven clock never goes back: asked for " + sim
                    + " µs, it is already at " + simMicros + " µs");
        }
        simMicros = sim;
    }
}
