package org.fdnet.corba.cli;

import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import org.HdrHistogram.Histogram;
import org.fdnet.corba.LinkSettings;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fdnet bench corba}: one run measures the bare JacORB two-way call (the baseline), the FDNet
 * cross-host hop and the sustained cross-host event rate, all on 127.0.0.1 with a host in a child JVM.
 */
@Command(name = "corba", mixinStandardHelpOptions = true,
        description = "Bare JacORB two-way call (baseline) vs the FDNet cross-host hop (p50/p99), and the sustained "
                + "cross-host event rate with zero loss.")
public final class CorbaBenchmark implements Runnable {
    @Option(names = "--samples", defaultValue = "20000", description = "latency samples per figure (default: ${DEFAULT-VALUE})")
    int samples;

    @Option(names = "--warmup", defaultValue = "5000", description = "warm-up calls before each figure (default: ${DEFAULT-VALUE})")
    int warmup;

    @Option(names = "--events", defaultValue = "2000000", description = "values streamed for the rate (default: ${DEFAULT-VALUE})")
    int events;

    @Option(names = "--window", defaultValue = "4", description = "calls in flight per link (default: ${DEFAULT-VALUE})")
    int window;

    @Option(names = "--batch", defaultValue = "4096", description = "values per call at most (default: ${DEFAULT-VALUE})")
    int batch;

    @Option(names = "--spin-micros", defaultValue = "" + LinkSettings.DEFAULT_SPIN_MICROS,
            description = "how long an idle link on bench-a and bench-probe watches for the next value before its"
                    + " sender parks; 0 = park at once (default: ${DEFAULT-VALUE})")
    int spinMicros;

    @Override
    public void run() {
        LinkSettings links = new LinkSettings(window, batch, 1 << 20, 200, spinMicros);
        System.out.printf("FDNet bench corba: JacORB 3.9 on 127.0.0.1, Java %s, %d cores; link window %d, batch <= %d,"
                        + " idle watch %d µs%n",
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors(), window, batch,
                spinMicros);
        System.out.println("starting: naming service (in-process), host bench-b (child JVM), hosts bench-a and "
                + "bench-probe (in-process) ...");
        try (BenchTopology topology = BenchTopology.start(links)) {
            System.out.println("topology: " + topology.describe());
            Histogram bare = measureBare(topology);
            HopResult hop = measureHop(topology);
            RateResult rate = measureRate(topology);
            print(bare, hop, rate, topology);
        }
    }

    private Histogram measureBare(BenchTopology t) {
        for (int i = 0; i < warmup; i++) {
            t.remoteHost().ping();
        }
        Histogram h = histogram();
        for (int i = 0; i < samples; i++) {
            long t0 = System.nanoTime();
            t.remoteHost().ping();
            h.recordValue(System.nanoTime() - t0);
        }
        return h;
    }

    private record HopResult(Histogram oneWay, Histogram loop, Histogram interleavedBare) {
    }

    /**
     * One sample at a time: write on A, wait until B's hop Data (the one-way time) reaches the probe, then
     * one bare call, so that a bare call is also measured in the conditions the hop samples see.
     */
    private HopResult measureHop(BenchTopology t) {
        BlockingQueue<long[]> arrivals = new ArrayBlockingQueue<>(16);
        AutoCloseable observation = t.observeHops((value, origin) -> {
            if (value instanceof Long oneWay && oneWay > 0) {
                arrivals.offer(new long[] {oneWay, System.nanoTime()});
            }
        });
        Histogram oneWay = histogram();
        Histogram loop = histogram();
        Histogram interleavedBare = histogram();
        try (observation) {
            for (int i = 0; i < warmup + samples; i++) {
                long t0 = System.nanoTime();
                t.writePing(t0);
                long[] arrival = arrivals.poll(10, TimeUnit.SECONDS);
                if (arrival == null) {
                    throw new IllegalStateException("hop sample " + i + " did not come back within 10 s");
                }
                // The same bare call, made in the hop's conditions (threads that waited, not a tight loop).
                long b0 = System.nanoTime();
                t.remoteHost().ping();
                long b1 = System.nanoTime();
                if (i >= warmup) {
                    oneWay.recordValue(arrival[0]);
                    loop.recordValue(arrival[1] - t0);
                    interleavedBare.recordValue(b1 - b0);
                }
            }
        } catch (Exception e) {
            throw new IllegalStateException("hop measurement failed: " + e.getMessage(), e);
        }
        return new HopResult(oneWay, loop, interleavedBare);
    }

    private record RateResult(long sent, long received, boolean inOrder, double seconds) {
        double perSecond() {
            return received / seconds;
        }
    }

    private RateResult measureRate(BenchTopology t) {
        long[] state = {0, 0, 1}; // next expected, last arrival nanos, in order (1/0)
        Object done = new Object();
        AutoCloseable observation = t.observeSeq((value, origin) -> {
            if (value instanceof Long v && v >= 0) {
                synchronized (done) {
                    if (v != state[0]) {
                        state[2] = 0;
                    }
                    state[0] = v + 1;
                    state[1] = System.nanoTime();
                    if (state[0] == events) {
                        done.notifyAll();
                    }
                }
            }
        });
        try (observation) {
            long start = System.nanoTime();
            for (long i = 0; i < events; i++) {
                t.writeSeq(i);
            }
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            synchronized (done) {
                while (state[0] < events && System.nanoTime() < deadline) {
                    done.wait(200);
                }
                return new RateResult(events, state[0], state[2] == 1, (state[1] - start) / 1e9);
            }
        } catch (Exception e) {
            throw new IllegalStateException("rate measurement failed: " + e.getMessage(), e);
        }
    }

    private void print(Histogram bare, HopResult hopResult, RateResult rate, BenchTopology t) {
        Histogram hop = hopResult.oneWay();
        double bareP50 = bare.getValueAtPercentile(50) / 1000.0;
        double hopP50 = hop.getValueAtPercentile(50) / 1000.0;
        System.out.println();
        System.out.printf("%-46s p50 %8.1f us   p99 %8.1f us   (%d samples)%n", "bare JacORB two-way call (baseline):",
                bareP50, bare.getValueAtPercentile(99) / 1000.0, bare.getTotalCount());
        System.out.printf("%-46s p50 %8.1f us   p99 %8.1f us   (%d samples)%n",
                "FDNet hop: Data on A -> Relation -> Data on B:", hopP50, hop.getValueAtPercentile(99) / 1000.0,
                hop.getTotalCount());
        System.out.printf("%-46s %.2f x the bare call (target <= 1.3)%n", "hop p50 / bare p50:", hopP50 / bareP50);
        Histogram ib = hopResult.interleavedBare();
        System.out.printf("%-46s p50 %8.1f us   p99 %8.1f us   (hop / this: %.2f)%n",
                "  bare call, interleaved with the hop samples:", ib.getValueAtPercentile(50) / 1000.0,
                ib.getValueAtPercentile(99) / 1000.0, hopP50 / (ib.getValueAtPercentile(50) / 1000.0));
        Histogram loop = hopResult.loop();
        System.out.printf("%-46s p50 %8.1f us   p99 %8.1f us   (%.2f x the bare call)%n",
                "  and on to an observer back on A (2 hops):", loop.getValueAtPercentile(50) / 1000.0,
                loop.getValueAtPercentile(99) / 1000.0, loop.getValueAtPercentile(50) / 1000.0 / bareP50);
        long lost = rate.sent() - rate.received();
        System.out.printf("%-46s %,.0f events/s; %,d sent, %,d received, %,d lost, %s (target >= 200,000/s)%n",
                "sustained cross-host rate:", rate.perSecond(), rate.sent(), rate.received(), lost,
                rate.inOrder() ? "in order" : "OUT OF ORDER");
        System.out.println("links: " + String.join("; ", List.of(t.linkReport())));
    }

    private static Histogram histogram() {
        return new Histogram(TimeUnit.SECONDS.toNanos(60), 3);
    }
}
