package org.fdnet.runtime.engine;

/**
 * Simulated time for a network run in steps: the driver (a simulator bridge, a test) moves it forward with
 * {@link RuntimeNetwork#advanceTo}; nothing else does. A network started with
 * {@link RuntimeOptions#drivenClock} has no timer thread and no worker threads: periods fall due when the
 * driver advances past them, and every firing runs on the driver's thread. Event stamps,
 * {@link RelationContext#now()} and {@link RelationContext#seconds()} all read this clock, so the same
 * network fed the same way produces the same events, time stamps included.
 */
public final class DrivenClock {
    private volatile long micros;

    /** A clock standing at {@code startMicros} (µs since the epoch; any fixed value makes runs comparable). */
    public DrivenClock(long startMicros) {
        if (startMicros < 0) {
            throw new IllegalArgumentException("a driven clock starts at 0 µs or later, was " + startMicros);
        }
        this.micros = startMicros;
    }

    /** The simulated time now, µs. */
    public long micros() {
        return micros;
    }

    /** Moves the clock; only {@link RuntimeNetwork#advanceTo} does, and never backwards. */
    void set(long newMicros) {
        if (newMicros < micros) {
            throw new IllegalArgumentException("a driven clock never goes back: at " + micros + " µs, asked for "
                    + newMicros + " µs");
        }
        micros = newMicros;
    }
}
