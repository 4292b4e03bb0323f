package org.fdnet.event;

import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongSupplier;

/**
 * Event times: microseconds since the epoch, unique and strictly increasing for every event this clock
 * stamps. One clock per core stamps all its sources, which makes the times strictly increasing per
 * source as the logger's key {@code (sourceid, time)} requires. When events come faster than one per
 * microsecond the clock runs ahead of the wall clock by a few microseconds and catches up when the
 * burst ends; it never goes backwards, even if the wall clock does. A clock may read another time source
 * than the wall (a simulated time for stepped runs): the same rules hold against that source.
 */
public final class EventClock {
    private final AtomicLong last = new AtomicLong();
    private final LongSupplier source;

    /** A clock on the wall time. */
    public EventClock() {
        this(EventClock::wallMicros);
    }

    /**
     * A clock on {@code microsSource} (µs since the epoch), e.g. a simulated time.
     *
     * @param microsSource the time source, µs since the epoch; read on every {@link #next()}
     */
    public EventClock(LongSupplier microsSource) {
        this.source = java.util.Objects.requireNonNull(microsSource, "microsSource");
    }

    /**
     * The next time: {@code max(now, previous + 1)}. Lock-free.
     *
     * @return µs since the epoch, above every time this clock gave before
     */
    public long next() {
        long now = source.getAsLong();
        while (true) {
            long previous = last.get();
            long candidate = Math.max(now, previous + 1);
            if (last.compareAndSet(previous, candidate)) {
                return candidate;
            }
        }
    }

    private static long wallMicros() {
        java.time.Instant now = java.time.Instant.now();
        return now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000L;
    }
}
