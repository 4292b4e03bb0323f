package org.fdnet.runtime.bench;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;
import org.HdrHistogram.Histogram;
import org.fdnet.event.EventSink;
import org.fdnet.event.client.ClientStatus;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;

/**
 * {@code fdnet bench core}: the in-process cost of FDNet's dataflow, each figure beside plain Java
 * doing the same work in the same run. Latencies are from {@code System.nanoTime()} before a Data write
 * to the moment the downstream Data's observer sees the result, recorded in HdrHistogram after a warm-up.
 */
public final class CoreBenchmark {
    private final PrintWriter out;
    private final int hops;
    private final int warmup;

    /** Where the observer of the last Data writes its arrival time and a sequence number. */
    private static final class Arrival {
        volatile long nanos;
        final AtomicLong count = new AtomicLong();
    }

    /** {@code HOST:PORT} of a running logger to send the hop's events to, or {@code null}. */
    private final String logger;

    public CoreBenchmark(PrintWriter out, int hops, int warmup) {
        this(out, hops, warmup, null);
    }

    public CoreBenchmark(PrintWriter out, int hops, int warmup, String logger) {
        this.out = out;
        this.hops = hops;
        this.warmup = warmup;
        this.logger = logger;
    }

    public record Result(double hopP50Micros, double chainFiringsPerSecond) {
    }

    public Result run() throws Exception {
        out.printf("fdnet bench core: JDK %s, %d cores; %,d measured hops after %,d warm-up%n",
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors(), hops, warmup);
        out.println();
        out.println("1. hop latency: Data write -> Relation (+1) -> Data write, seen by an observer");
        String row = "   %-44s p50 %8.3f us   p99 %8.3f us   p99.9 %8.3f us%n";
        Histogram base = baselineHop();
        // one untimed pass first: the JIT compiles the engine's paths before any figure is taken
        hop(RuntimeOptions.defaults().workerThreads(1).sink(new CountingSink()), hops / 2, warmup);
        Histogram events = hop(RuntimeOptions.defaults().workerThreads(1).sink(new CountingSink()), hops, warmup);
        Histogram inline = hop(RuntimeOptions.defaults().workerThreads(1), hops, warmup);
        Histogram pooled = hop(RuntimeOptions.defaults().workerThreads(1).inlineCallers(false),
                Math.max(1000, hops / 20), Math.max(1000, warmup / 20));
        print(row, "baseline: plain Java calls", base);
        print(row, "FDNet, run on the writer's thread", inline);
        print(row, "FDNet, run on the writer's thread + events", events);
        print(row, "FDNet, handed to the worker pool", pooled);
        if (logger != null) {
            loggerHop(row);
        }
        out.println();

        out.println("2. throughput of a chain of 10 Relations, one writer thread (firings per second)");
        int writes = Math.max(10_000, hops / 2);
        double basePerSecond = baselineChain(10, writes);
        double chainPerSecond = chain(10, writes);
        out.printf(Locale.ROOT, "   %-44s %,14.0f /s%n", "baseline: plain Java calls", basePerSecond);
        out.printf(Locale.ROOT, "   %-44s %,14.0f /s  (%.1f%% of baseline)%n", "FDNet", chainPerSecond,
                100 * chainPerSecond / basePerSecond);
        out.println();

        out.println("3. fan-out 1 -> 100 Relations: time until all 100 outputs are written, and firings per second");
        int fanWrites = Math.max(2_000, hops / 50);
        FanOut baseFan = baselineFanOut(100, fanWrites);
        FanOut fan = fanOut(100, fanWrites, 1);
        FanOut fanTwo = fanOut(100, fanWrites, Runtime.getRuntime().availableProcessors());
        String fanRow = "   %-44s p50 %8.2f us   p99 %8.2f us   %,12.0f firings/s%n";
        out.printf(Locale.ROOT, fanRow, "baseline: plain Java calls", baseFan.p50(), baseFan.p99(), baseFan.perSecond());
        out.printf(Locale.ROOT, fanRow, "FDNet, 1 worker", fan.p50(), fan.p99(), fan.perSecond());
        out.printf(Locale.ROOT, fanRow, "FDNet, " + Runtime.getRuntime().availableProcessors() + " workers", fanTwo.p50(),
                fanTwo.p99(), fanTwo.perSecond());
        out.println();
        double p50 = inline.getValueAtPercentile(50) / 1000.0;
        out.printf(Locale.ROOT, "targets: hop p50 <= 2 us: %s (%.3f us); >= 1 M firings/s on one core: %s (%,.0f /s)%n",
                p50 <= 2.0 ? "met" : "NOT met", p50, chainPerSecond >= 1e6 ? "met" : "NOT met", chainPerSecond);
        out.flush();
        return new Result(p50, chainPerSecond);
    }

    private void print(String row, String label, Histogram h) {
        out.printf(Locale.ROOT, row, label, h.getValueAtPercentile(50) / 1000.0, h.getValueAtPercentile(99) / 1000.0,
                h.getValueAtPercentile(99.9) / 1000.0);
    }

    private static Histogram hop(RuntimeOptions options, int samples, int warm) throws Exception {
        Histogram h = new Histogram(3_600_000_000L, 3);
        try (RuntimeNetwork net = BenchNetworks.start(BenchNetworks.chain(1), options)) {
            Controller c = net.controller();
            NodeRef in = BenchNetworks.ref("D0");
            Arrival arrival = new Arrival();
            c.observe(BenchNetworks.ref("D1"), (d, id, v) -> {
                arrival.nanos = System.nanoTime();
                arrival.count.incrementAndGet();
            });
            net.awaitQuiet(5, java.util.concurrent.TimeUnit.SECONDS);
            long expected = arrival.count.get();
            for (int i = 0; i < warm + samples; i++) {
                long t0 = System.nanoTime();
                c.setValue(in, Value.of((double) i));
                expected++;
                while (arrival.count.get() < expected) {
                    Thread.onSpinWait();
                }
                if (i >= warm) {
                    h.recordValue(Math.max(0, arrival.nanos - t0));
                }
            }
        }
        return h;
    }

    /**
     * The hop with a real logger client attached (two events per hop go to the logger at {@link #logger}), beside
     * the same hop with no sink in the same run: the core's cost per event with a logger. Fewer hops than the
     * others, and room in the client's memory for all their events, so that no event goes to its disk journal
     * (the figure is the core's, not the disk's); then every event is waited for until the logger committed it.
     */
    private void loggerHop(String row) throws Exception {
        int samples = Math.min(hops, 100_000);
        int warm = Math.min(warmup, 100_000);
        LoggerClientSettings settings = LoggerClientSettings.parseAddress(logger, "bench-core")
                .withMemoryEvents(4 * (samples + warm) + 1000);
        Histogram none = hop(RuntimeOptions.defaults().workerThreads(1), samples, warm);
        Histogram attached;
        ClientStatus status;
        try (LoggerClient client = new LoggerClient(settings)) {
            attached = hop(RuntimeOptions.defaults().workerThreads(1).sink(client), samples, warm);
            client.flush(600_000);
            status = client.status();
        }
        print(row, "FDNet, run on the writer's thread (again)", none);
        print(row, "FDNet, + events to the logger at " + logger, attached);
        out.printf(Locale.ROOT, "   %-44s %+8.3f us per hop (2 events) at p50; logger: %,d accepted, %,d committed, %,d lost%n",
                "cost of the logger client", (attached.getValueAtPercentile(50) - none.getValueAtPercentile(50)) / 1000.0,
                status.accepted(), status.acked(), status.lost());
    }

    private Histogram baselineHop() {
        Histogram h = new Histogram(3_600_000_000L, 3);
        PlainRelay.Cell in = new PlainRelay.Cell();
        PlainRelay.Cell outCell = new PlainRelay.Cell();
        Arrival arrival = new Arrival();
        in.next = PlainRelay.hop(outCell);
        outCell.next = v -> {
            arrival.nanos = System.nanoTime();
            arrival.count.incrementAndGet();
        };
        for (int i = 0; i < warmup + hops; i++) {
            long t0 = System.nanoTime();
            in.set(i);
            if (i >= warmup) {
                h.recordValue(Math.max(0, arrival.nanos - t0));
            }
        }
        return h;
    }

    private static double chain(int length, int writes) throws Exception {
        try (RuntimeNetwork net = BenchNetworks.start(BenchNetworks.chain(length), RuntimeOptions.defaults().workerThreads(1))) {
            Controller c = net.controller();
            NodeRef in = BenchNetworks.ref("D0");
            for (int i = 0; i < writes; i++) {
                c.setValue(in, Value.of((double) i));
            }
            net.awaitQuiet(5, java.util.concurrent.TimeUnit.SECONDS);
            long before = net.firings();
            long t0 = System.nanoTime();
            for (int i = 0; i < writes; i++) {
                c.setValue(in, Value.of((double) i));
            }
            net.awaitQuiet(10, java.util.concurrent.TimeUnit.SECONDS);
            long elapsed = System.nanoTime() - t0;
            double last = c.value(BenchNetworks.ref("D" + length)).asDouble();
            if (last != writes - 1 + length) {
                throw new IllegalStateException("chain lost its last value: " + last);
            }
            return (net.firings() - before) / (elapsed / 1e9);
        }
    }

    private static double baselineChain(int length, int writes) {
        PlainRelay.Cell first = new PlainRelay.Cell();
        PlainRelay.Cell at = first;
        for (int i = 0; i < length; i++) {
            PlainRelay.Cell next = new PlainRelay.Cell();
            at.next = PlainRelay.hop(next);
            at = next;
        }
        for (int i = 0; i < writes; i++) {
            first.set(i);
        }
        long t0 = System.nanoTime();
        for (int i = 0; i < writes; i++) {
            first.set(i);
        }
        long elapsed = System.nanoTime() - t0;
        if (at.value != writes - 1 + length) {
            throw new IllegalStateException("baseline chain is wrong: " + at.value);
        }
        return (double) writes * length / (elapsed / 1e9);
    }

    record FanOut(double p50, double p99, double perSecond) {
    }

    private static FanOut fanOut(int width, int writes, int workers) throws Exception {
        Histogram h = new Histogram(3_600_000_000L, 3);
        try (RuntimeNetwork net = BenchNetworks.start(BenchNetworks.fanOut(width), RuntimeOptions.defaults().workerThreads(workers))) {
            Controller c = net.controller();
            Arrival arrival = new Arrival();
            for (int i = 0; i < width; i++) {
                c.observe(BenchNetworks.ref("Out" + i), (d, id, v) -> {
                    arrival.count.incrementAndGet();
                    arrival.nanos = System.nanoTime();
                });
            }
            net.awaitQuiet(5, java.util.concurrent.TimeUnit.SECONDS);
            NodeRef in = BenchNetworks.ref("In");
            long expected = arrival.count.get();
            long measuredStart = 0;
            long firingsBefore = 0;
            int warm = writes / 2;
            for (int i = 0; i < warm + writes; i++) {
                if (i == warm) {
                    measuredStart = System.nanoTime();
                    firingsBefore = net.firings();
                }
                long t0 = System.nanoTime();
                c.setValue(in, Value.of((double) i));
                expected += width;
                while (arrival.count.get() < expected) {
                    Thread.onSpinWait();
                }
                if (i >= warm) {
                    h.recordValue(Math.max(0, arrival.nanos - t0));
                }
            }
            double seconds = (System.nanoTime() - measuredStart) / 1e9;
            return new FanOut(h.getValueAtPercentile(50) / 1000.0, h.getValueAtPercentile(99) / 1000.0,
                    (net.firings() - firingsBefore) / seconds);
        }
    }

    private static FanOut baselineFanOut(int width, int writes) {
        Histogram h = new Histogram(3_600_000_000L, 3);
        PlainRelay.Cell in = new PlainRelay.Cell();
        PlainRelay.Consumer[] relays = new PlainRelay.Consumer[width];
        Arrival arrival = new Arrival();
        for (int i = 0; i < width; i++) {
            PlainRelay.Cell outCell = new PlainRelay.Cell();
            outCell.next = v -> {
                arrival.count.incrementAndGet();
                arrival.nanos = System.nanoTime();
            };
            relays[i] = PlainRelay.hop(outCell);
        }
        in.next = v -> {
            for (PlainRelay.Consumer r : relays) {
                r.accept(v);
            }
        };
        int warm = writes / 2;
        long start = 0;
        for (int i = 0; i < warm + writes; i++) {
            if (i == warm) {
                start = System.nanoTime();
            }
            long t0 = System.nanoTime();
            in.set(i);
            if (i >= warm) {
                h.recordValue(Math.max(0, arrival.nanos - t0));
            }
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        return new FanOut(h.getValueAtPercentile(50) / 1000.0, h.getValueAtPercentile(99) / 1000.0,
                (double) writes * width / seconds);
    }

    /** Counts events: the cheapest real sink, to show what building events costs. */
    private static final class CountingSink implements EventSink {
        private final java.util.concurrent.atomic.LongAdder count = new java.util.concurrent.atomic.LongAdder();

        @Override
        public void accept(org.fdnet.event.NetworkEvent event) {
            count.increment();
        }
    }
}
