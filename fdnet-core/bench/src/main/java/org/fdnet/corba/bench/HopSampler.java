package org.fdnet.corba.bench;

import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.HdrHistogram.Histogram;

/**
 * Takes the samples of {@code bench corba}'s latency figures, one at a time, either back to back or one
 * every {@code gap} (a sensor's rhythm: the links and ORB threads are idle in between):
 *
 * <pre>
 *   write nanoTime t0 into bench-a:ping ──▶ bench-b:stamp (one-way = now - t0) ──▶ bench-a:hop ──▶ observer
 *   round trip = arrival in bench-a's JVM - t0            one-way = what stamp wrote
 *   baseline: bench-b's Host.ping() from bench-a's ORB, a bare JacORB two-way call, timed on bench-a
 * </pre>
 */
final class HopSampler implements AutoCloseable {
    private final BenchTopology topology;
    private final BlockingQueue<long[]> arrivals = new ArrayBlockingQueue<>(16);
    private final AutoCloseable observation;

    /** A figure's samples: the round trip, the one-way part of it and bare calls taken between them. */
    record Samples(Histogram roundTrip, Histogram oneWay, Histogram interleavedBare) {
    }

    HopSampler(BenchTopology topology) {
        this.topology = topology;
        this.observation = topology.observeHops((value, fromHost, origin) -> {
            if (value instanceof Long oneWay && oneWay > 0) {
                arrivals.offer(new long[] {oneWay, System.nanoTime()});
            }
        });
    }

    /**
     * {@code warmup + count} round trips, the next one {@code gapNanos} after the previous started (0: as
     * soon as it is back); with {@code interleave}, one bare call right after each (the same call in the
     * conditions the hop sees: threads that just waited, not a tight loop).
     */
    Samples hops(int warmup, int count, long gapNanos, boolean interleave) {
        Histogram roundTrip = histogram();
        Histogram oneWay = histogram();
        Histogram bare = histogram();
        long tick = System.nanoTime();
        for (int i = 0; i < warmup + count; i++) {
            tick = awaitTick(tick, gapNanos);
            long t0 = System.nanoTime();
            topology.writePing(t0);
            long[] arrival = awaitArrival(i);
            long b0 = 0;
            long b1 = 0;
            if (interleave) {
                b0 = System.nanoTime();
                topology.remoteHost().ping();
                b1 = System.nanoTime();
            }
            if (i >= warmup) {
                roundTrip.recordValue(arrival[1] - t0);
                oneWay.recordValue(arrival[0]);
                if (interleave) {
                    bare.recordValue(b1 - b0);
                }
            }
        }
        return new Samples(roundTrip, oneWay, bare);
    }

    /** {@code warmup + count} bare two-way calls, one every {@code gapNanos} (0: back to back). */
    Histogram bare(int warmup, int count, long gapNanos) {
        Histogram h = histogram();
        long tick = System.nanoTime();
        for (int i = 0; i < warmup + count; i++) {
            tick = awaitTick(tick, gapNanos);
            long t0 = System.nanoTime();
            topology.remoteHost().ping();
            long elapsed = System.nanoTime() - t0;
            if (i >= warmup) {
                h.recordValue(elapsed);
            }
        }
        return h;
    }

    /** Sleeps until {@code previous + gap} (at once if that has passed); returns the tick to start from. */
    private static long awaitTick(long previous, long gapNanos) {
        if (gapNanos == 0) {
            return previous;
        }
        long due = previous + gapNanos;
        long now;
        while ((now = System.nanoTime()) < due) {
            LockSupport.parkNanos(due - now);
        }
        return Math.max(due, now - gapNanos / 2); // when late (a loaded machine), do not catch up in a burst
    }

    private long[] awaitArrival(int sample) {
        try {
            long[] arrival = arrivals.poll(10, TimeUnit.SECONDS);
            if (arrival == null) {
                throw new IllegalStateException("hop sample " + sample + " did not come back to bench-a within 10 s");
            }
            return arrival;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for hop sample " + sample, e);
        }
    }

    static Histogram histogram() {
        return new Histogram(TimeUnit.SECONDS.toNanos(60), 3);
    }

    @Override
    public void close() {
        try {
            observation.close();
        } catch (Exception e) {
            throw new IllegalStateException("cannot stop observing the hop Data: " + e.getMessage(), e);
        }
    }
}
