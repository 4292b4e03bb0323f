package org.fdnet.event;

import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongSupplier;

/**
 * Event times: microseconds since the epoch, unique and strictly increasing for every event this clock
 * stamps. One clock per core stamps all its sources, which makes the times strictly increasing per
 * source as the logger's key {@code (sourceid, time)} requires. When events come faster than one per
 * microsecond the clock runs ahead of the wall clock by a few microseconds and catches up when the
 * burst ends; it never goes backwards, even if the wall clock does.
 *
 * <p>A clock may read another time source than the wall (a simulator's driven time): the same rule then
 * makes a stepped run's stamps a pure function of the simulated time and the order of events.
 */
public final class EventClock {
    private final AtomicLong last = new AtomicLong();
    private final LongSupplier micros;

    /** A clock on the wall time. */
    public EventClock() {
        this(EventClock::wallMicros);
    }

    /** A clock on {@code micros}, a source of µs since the epoch (e.g. simulated time). */
    public EventClock(LongSupplier micros) {
        this.micros = java.util.Objects.requireNonNull(micros, "micros");
    }

    /** The next time: {@code max(now, previous + 1)}. Lock-free. */
    public long next() {
        long now = micros.getAsLong();
        while (true) {
            long previous = last.get();
            long candidate = Math.max(now, previous + 1);
            if (last.compareAndSet(previous, candidate)) {
                return candidate;
            }
        }
    }

    /** The wall time in µs since the epoch. */
    public static long wallMicros() {
        java.time.Instant now = java.time.Instant.now();
        return now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000L;
    }
}
