package org.fdnet.corba.bench;

import java.nio.file.Files;
import org.fdnet.tls.KeyMaker;
import org.fdnet.tls.TlsIdentity;
import org.fdnet.tls.TransportSecurity;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.HdrHistogram.Histogram;
import org.fdnet.corba.CpuLatencyHold;
import org.fdnet.corba.LinkSettings;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code fdnet bench corba}: one run, all on 127.0.0.1 with a host in a child JVM, measures
 * <ol>
 *   <li>the round trip A → B → back to A (two hops through the real links and a Relation on B) against
 *       the bare JacORB two-way call (the headline ratio), and the one-way part of it against half the
 *       bare round trip;</li>
 *   <li>the same at realistic gaps (a value every 1, 10 and 100 ms: the links idle in between), each beside
 *       the bare call at the same gap, with the CPU both JVMs used in each phase (what the idle watch costs);</li>
 *   <li>the sustained cross-host rate over {@code --seconds}, counting what arrives, per 10 s window.</li>
 * </ol>
 */
@Command(name = "corba", mixinStandardHelpOptions = true,
        description = {"Round trip A -> B -> back to A's JVM through FDNet links vs the bare JacORB two-way call (target <= 1.3x),",
            "the one-way hop vs half the bare round trip, both again at values every 1, 10 and 100 ms",
            "with the CPU used, and the sustained cross-host rate over --seconds, counted on arrival."})
public final class CorbaBenchmark implements Runnable {
    private static final double TARGET_RATIO = 1.3;
    private static final long RATE_TARGET = 2_000_000;
    private static final long[] GAPS_MILLIS = {1, 10, 100};
    private static final long WINDOW_SECONDS = 10;

    @Option(names = "--samples", defaultValue = "20000", description = "back-to-back latency samples per figure (default: ${DEFAULT-VALUE})")
    int samples;

    @Option(names = "--warmup", defaultValue = "5000", description = "warm-up calls before each back-to-back figure (default: ${DEFAULT-VALUE})")
    int warmup;

    @Option(names = "--idle-samples", defaultValue = "300",
            description = "samples per figure at each idle gap; at least 3 s of them (default: ${DEFAULT-VALUE})")
    int idleSamples;

    @Option(names = "--seconds", defaultValue = "60", description = "how long the sustained stream is written (default: ${DEFAULT-VALUE})")
    int seconds;

    @Option(names = "--window", defaultValue = "4", description = "calls in flight per link (default: ${DEFAULT-VALUE})")
    int window;

    @Option(names = "--batch", defaultValue = "4096", description = "values per call at most (default: ${DEFAULT-VALUE})")
    int batch;

    @Option(names = "--spin-micros", defaultValue = "" + LinkSettings.DEFAULT_SPIN_MICROS,
            description = "how long an idle link on bench-a and bench-probe watches for the next value before its"
                    + " sender parks; 0 = park at once. bench-b (an fdnet host) keeps the default (default: ${DEFAULT-VALUE})")
    int spinMicros;

    @Option(names = "--hold-cpu-latency", description = "keep every CPU out of deep idle states for the whole run, baseline"
            + " included (/dev/cpu_dma_latency at 0, as fdnet host --hold-cpu-latency does; needs root)")
    boolean holdCpuLatency;

    @Option(names = "--tls", description = "then measure back to back and sustained again over mutual TLS (throwaway"
            + " keys made with fdnet keys' maker) and print the TLS cost beside the plain figures")
    boolean tls;

    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        if (samples < 1 || warmup < 0 || idleSamples < 1 || seconds < 1) {
            throw new ParameterException(spec.commandLine(),
                    "--samples, --idle-samples and --seconds must be at least 1, --warmup at least 0");
        }
        try (CpuLatencyHold held = holdCpuLatency ? CpuLatencyHold.hold() : null) {
            measure();
        }
    }

    private void measure() {
        LinkSettings links = new LinkSettings(window, batch, 1 << 20, 200, spinMicros);
        System.out.printf("FDNet bench corba: JacORB 3.9 on 127.0.0.1, Java %s, %d cores; link window %d, batch <= %d,"
                        + " idle watch %d µs on bench-a (bench-b: the default, %d µs)%n",
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors(), window, batch,
                spinMicros, LinkSettings.DEFAULT_SPIN_MICROS);
        System.out.println("CPU wake-up latency: " + (holdCpuLatency ? "held at 0 µs by this benchmark, baseline included"
                : "the machine's own (idle CPUs may sleep; --hold-cpu-latency keeps them awake)"));
        System.out.println("starting: naming service (in-process), host bench-b (child JVM), hosts bench-a and "
                + "bench-probe (in-process) ...");
        Figures plain;
        try (BenchTopology topology = BenchTopology.start(links); HopSampler sampler = new HopSampler(topology)) {
            System.out.println("topology: " + topology.describe());
            Histogram[] calls = backToBack(sampler);
            idleGaps(sampler, new CpuClock(topology.remotePid()));
            plain = new Figures(calls[0], calls[1], sustained(topology));
            System.out.println("links on bench-a: " + String.join("; ", List.of(topology.linkReport())));
        }
        if (tls) {
            tlsCost(links, plain);
        }
    }

    /** The back-to-back and sustained figures of one topology. */
    private record Figures(Histogram bare, Histogram roundTrip, double rate) {
    }

    private void tlsCost(LinkSettings links, Figures plain) {
        System.out.println();
        progress("again over mutual TLS: throwaway keys for bench-a and bench-b, every ORB with --tls ...");
        try {
            KeyMaker maker = new KeyMaker(Files.createTempDirectory("fdnet-bench-keys-"));
            Figures secure;
            try {
                maker.make(List.of("bench-a", "bench-b"));
                TransportSecurity.use(TlsIdentity.load(maker.store("bench-a")));
                try (BenchTopology topology = BenchTopology.start(links, List.of("--tls", maker.store("bench-b").toString()));
                     HopSampler sampler = new HopSampler(topology)) {
                    Histogram[] calls = backToBack(sampler);
                    secure = new Figures(calls[0], calls[1], sustained(topology));
                }
            } finally {
                TransportSecurity.off();
                maker.deleteAll();
            }
            System.out.println();
            System.out.println("TLS cost (same machine, same run; TLS 1.3, EC P-256, mutual authentication):");
            System.out.printf("  %-36s %12s %12s %8s%n", "", "plain", "TLS", "TLS/plain");
            cost("bare two-way call p50 (us)", p50(plain.bare()), p50(secure.bare()));
            cost("bare two-way call p99 (us)", p99(plain.bare()), p99(secure.bare()));
            cost("round trip A -> B -> back p50 (us)", p50(plain.roundTrip()), p50(secure.roundTrip()));
            cost("round trip A -> B -> back p99 (us)", p99(plain.roundTrip()), p99(secure.roundTrip()));
            cost("sustained values/s", plain.rate(), secure.rate());
        } catch (java.io.IOException e) {
            throw new IllegalStateException("cannot make the benchmark's TLS keys: " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static void cost(String label, double plain, double secure) {
        System.out.printf("  %-36s %,12.1f %,12.1f %8.2f%n", label, plain, secure, secure / plain);
    }

    private static double p99(Histogram h) {
        return h.getValueAtPercentile(99) / 1000.0;
    }

    /** Prints the back-to-back figures; returns the bare calls and the round trips. */
    private Histogram[] backToBack(HopSampler sampler) {
        progress("back to back: %d bare calls, then %d round trips (+ %d warm-up each) ...", samples, samples, warmup);
        Histogram bare = sampler.bare(warmup, samples, 0);
        HopSampler.Samples hop = sampler.hops(warmup, samples, 0, true);
        double bareP50 = p50(bare);
        System.out.println();
        System.out.println("back to back (the next value as soon as the previous one is back):");
        line("bare JacORB two-way call (baseline)", bare);
        line("FDNet round trip A -> B -> back (2 hops)", hop.roundTrip());
        System.out.printf("%-50s %.2f x the bare call (target <= %.1f): %s%n", "ROUND TRIP p50 / bare p50:",
                p50(hop.roundTrip()) / bareP50, TARGET_RATIO, verdict(p50(hop.roundTrip()) / bareP50 <= TARGET_RATIO));
        line("  bare call interleaved with the round trips", hop.interleavedBare());
        line("FDNet one-way: write on A -> Relation on B", hop.oneWay());
        System.out.printf("%-50s p50 %8.1f us   (half the bare round trip: a one-way baseline, not measured)%n",
                "one-way baseline: bare p50 / 2", bareP50 / 2);
        System.out.printf("%-50s %.2f x half the bare call%n", "one-way p50 / (bare p50 / 2):", p50(hop.oneWay()) / (bareP50 / 2));
        return new Histogram[] {bare, hop.roundTrip()};
    }

    private void idleGaps(HopSampler sampler, CpuClock cpu) {
        System.out.println();
        System.out.println("idle links: one value every GAP (bare calls at the same gap first); CPU in cores (1.0 = a whole"
                + " core) of this JVM (bench-a, bench-probe) + bench-b's JVM over each phase");
        System.out.printf("%-7s %7s %-19s %-19s %6s %-7s %-19s %-13s %-13s%n", "gap", "samples", "bare p50/p99 us",
                "round trip p50/p99", "ratio", "target", "one-way p50/p99", "CPU bare", "CPU hops");
        for (long gapMillis : GAPS_MILLIS) {
            long gap = TimeUnit.MILLISECONDS.toNanos(gapMillis);
            int count = (int) Math.max(idleSamples, 3000 / gapMillis);
            progress("  gap %d ms: %d bare calls, then %d round trips (~%d s) ...", gapMillis, count, count,
                    2 * count * gapMillis / 1000);
            CpuClock.Reading b0 = cpu.now();
            Histogram bare = sampler.bare(3, count, gap);
            CpuClock.Usage bareCpu = cpu.since(b0);
            CpuClock.Reading h0 = cpu.now();
            HopSampler.Samples hop = sampler.hops(3, count, gap, false);
            CpuClock.Usage hopCpu = cpu.since(h0);
            double ratio = p50(hop.roundTrip()) / p50(bare);
            System.out.printf("%-7s %7d %-19s %-19s %6.2f %-7s %-19s %-13s %-13s%n", gapMillis + " ms", count,
                    pair(bare), pair(hop.roundTrip()), ratio, verdict(ratio <= TARGET_RATIO), pair(hop.oneWay()),
                    cores(bareCpu), cores(hopCpu));
        }
    }

    /** Prints the sustained figures; returns the rate in values per second. */
    private double sustained(BenchTopology topology) {
        progress("%nsustained: writing seq on bench-a as fast as one thread can for %d s ...", seconds);
        ArrivalCount count = new ArrivalCount(TimeUnit.SECONDS.toNanos(WINDOW_SECONDS));
        long sent = 0;
        try (AutoCloseable observation = topology.observeSeq((value, fromHost, origin) -> {
            if (value instanceof Long v && v >= 0) {
                count.arrived(v, System.nanoTime());
            }
        })) {
            long start = System.nanoTime();
            count.start(start);
            long end = start + TimeUnit.SECONDS.toNanos(seconds);
            long nextReport = start + TimeUnit.SECONDS.toNanos(WINDOW_SECONDS);
            while (true) {
                for (int i = 0; i < 1024; i++) {
                    topology.writeSeq(sent++);
                }
                long now = System.nanoTime();
                if (now >= end) {
                    break;
                }
                if (now >= nextReport) {
                    progress("  %d s: %,d written, %,d arrived", (now - start) / 1_000_000_000L, sent, count.received());
                    nextReport += TimeUnit.SECONDS.toNanos(WINDOW_SECONDS);
                }
            }
            awaitDrain(count, sent);
        } catch (Exception e) {
            throw new IllegalStateException("sustained measurement failed: " + e.getMessage(), e);
        }
        long received = count.received();
        double rate = received / count.seconds();
        System.out.printf("%-50s %,.0f values/s over %.1f s; %,d written, %,d counted on arrival, %,d lost, %,d out of"
                        + " sequence (target >= %,d/s with 0 lost): %s%n", "sustained cross-host rate (A -> B -> probe):",
                rate, count.seconds(), sent, received, sent - received, count.unexpected(), RATE_TARGET,
                verdict(rate >= RATE_TARGET && received == sent && count.unexpected() == 0));
        StringBuilder windows = new StringBuilder();
        long[] perWindow = count.perWindow();
        for (int i = 0; i < perWindow.length; i++) {
            windows.append(String.format("%s%d-%d s: %,d/s", i == 0 ? "" : "; ", i * WINDOW_SECONDS,
                    (i + 1) * WINDOW_SECONDS, perWindow[i] / WINDOW_SECONDS));
        }
        System.out.println("  arrivals per " + WINDOW_SECONDS + " s window: " + windows);
        return rate;
    }

    /** Waits until every written value has arrived, or nothing has arrived for 30 s. */
    private static void awaitDrain(ArrivalCount count, long sent) throws InterruptedException {
        long seen = -1;
        long quietSince = System.nanoTime();
        while (count.received() < sent) {
            long now = count.received();
            if (now != seen) {
                seen = now;
                quietSince = System.nanoTime();
            } else if (System.nanoTime() - quietSince > TimeUnit.SECONDS.toNanos(30)) {
                return;
            }
            Thread.sleep(20);
        }
    }

    private static void progress(String format, Object... args) {
        System.out.printf(format + "%n", args);
        System.out.flush();
    }

    private static void line(String label, Histogram h) {
        System.out.printf("%-50s p50 %8.1f us   p99 %8.1f us   (%d samples)%n", label + ":", p50(h),
                h.getValueAtPercentile(99) / 1000.0, h.getTotalCount());
    }

    private static double p50(Histogram h) {
        return h.getValueAtPercentile(50) / 1000.0;
    }

    private static String pair(Histogram h) {
        return String.format("%.1f / %.1f", p50(h), h.getValueAtPercentile(99) / 1000.0);
    }

    private static String cores(CpuClock.Usage u) {
        return String.format("%.3f+%.3f", u.thisJvmCores(), u.childCores());
    }

    private static String verdict(boolean met) {
        return met ? "met" : "MISSED";
    }
}
