package org.fdnet.corba;

/**
 * Flow control of one cross-host link: how many values may wait, how many go in one call and how many
 * calls may be in flight at once. Validated here, so a link never runs with a window of zero.
 *
 * @param window      two-way {@code deliver} calls in flight at once (JacORB's POA queue never sees more)
 * @param batchMax    values in one call at most; fewer when fewer are waiting (latency stays one call)
 * @param capacity    values a link holds that its peer has not acknowledged; a power of two. When full, a
 *                    writer waits while the peer is reachable (no loss) and the oldest value is dropped
 *                    and counted while the peer is down (a dead host never stops a live one)
 * @param retryMillis how often a broken link tries its peer again
 * @param spinMicros  how long an idle link's sender watches for the next value before it parks (0: never
 *                    spins). Waking a parked thread costs the first value of a burst several µs of latency;
 *                    the watch is bounded (one per idle spell) and yields the core, so an idle link costs
 *                    nothing once it expires, but each idle spell shorter than the rhythm costs the watch
 */
public record LinkSettings(int window, int batchMax, int capacity, int retryMillis, int spinMicros) {
    /**
     * Park at once. The watch only pays off for values closer together than the watch is long; the rates
     * links carry (a value every 1 ms for a 1 kHz joint loop, 10 ms for a 100 Hz sensor, 100 ms for a 10 Hz
     * planner) are all farther apart than any watch worth its CPU, so each value would pay the wake-up anyway
     * plus a watch of CPU (300 µs at 1 kHz: 0.3 of a core per link; {@code fdnet bench corba} measures it).
     * A link whose values come in bursts closer than a few hundred µs can set a watch.
     */
    public static final int DEFAULT_SPIN_MICROS = 0;

    public LinkSettings {
        if (window < 1 || window > 64) {
            throw new IllegalArgumentException("window must be 1..64, was " + window);
        }
        if (batchMax < 1) {
            throw new IllegalArgumentException("batchMax must be at least 1, was " + batchMax);
        }
        if (capacity < batchMax || Integer.bitCount(capacity) != 1) {
            throw new IllegalArgumentException("capacity must be a power of two and at least batchMax ("
                    + batchMax + "), was " + capacity);
        }
        if (retryMillis < 1) {
            throw new IllegalArgumentException("retryMillis must be at least 1, was " + retryMillis);
        }
        if (spinMicros < 0 || spinMicros > 10_000) {
            throw new IllegalArgumentException("spinMicros must be 0..10000, was " + spinMicros);
        }
    }

    public LinkSettings(int window, int batchMax, int capacity, int retryMillis) {
        this(window, batchMax, capacity, retryMillis, DEFAULT_SPIN_MICROS);
    }

    public static LinkSettings defaults() {
        return new LinkSettings(4, 4096, 1 << 20, 200, DEFAULT_SPIN_MICROS);
    }

    public LinkSettings withWindow(int newWindow) {
        return new LinkSettings(newWindow, batchMax, capacity, retryMillis, spinMicros);
    }
}
