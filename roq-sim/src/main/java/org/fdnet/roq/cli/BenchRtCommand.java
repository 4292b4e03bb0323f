package org.fdnet.roq.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.JointCommand;
import org.fdnet.roq.sim.LoopStatistics;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.roq.sim.SimOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fdnet bench rt}: the real-time joint loop's wake-up latency and overruns while Java reads snapshots and
 * sends commands at 100 Hz, then, in the same run, {@code cyclictest} (Debian rt-tests) with the same interval
 * (1000 µs), priority and memory locking as the baseline: the best this machine's kernel gives any 1 kHz thread.
 */
@Command(name = "rt", mixinStandardHelpOptions = true,
        description = "Real-time loop wake-up latency and overruns beside cyclictest (same interval and priority, same run).")
public final class BenchRtCommand implements Callable<Integer> {
    @Option(names = "--seconds", defaultValue = "60", description = "seconds for the loop and again for cyclictest (default 60)")
    int seconds;

    @Option(names = "--priority", defaultValue = "80", description = "SCHED_FIFO priority of both (default 80)")
    int priority;

    @Override
    public Integer call() throws Exception {
        if (seconds < 1) {
            System.err.println("fdnet bench rt: --seconds must be at least 1");
            return 2;
        }
        System.out.printf(Locale.ROOT, "fdnet bench rt: %d s of the joint loop (1 kHz, SCHED_FIFO %d), then %d s of "
                + "cyclictest -m -p%d -i1000%n", seconds, priority, seconds, priority);
        LoopStatistics stats = new LoopStatistics();
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimOptions.of(SimMode.REAL_TIME).withPriority(priority))) {
            SensorSnapshot s = new SensorSnapshot();
            JointCommand command = new JointCommand();
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
            long nextReport = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (System.nanoTime() < end) {
                Thread.sleep(10);
                sim.read(s);
                command.basedOnTick(s.tick()).target(0, 0.1 * Math.sin(s.simTime()));
                sim.send(command);
                if (System.nanoTime() >= nextReport) {
                    sim.statistics(stats);
                    System.out.printf(Locale.ROOT, "  %6d ticks: p99 %d µs, max %d µs, overruns %d%n", stats.ticks(),
                            stats.latencyPercentileNanos(99) / 1000, stats.maxLatencyNanos() / 1000, stats.overruns());
                    nextReport += TimeUnit.SECONDS.toNanos(10);
                }
            }
            sim.statistics(stats);
        }
        long[] cyclic = cyclictest();
        System.out.printf(Locale.ROOT, "roq-sim joint loop: %d wake-ups, p50 %d µs, p99 %d µs, max %d µs; longest tick %d µs; "
                        + "overruns %d (worst %d µs past the next deadline); SCHED_FIFO %s, mlockall %s, cpu_dma_latency %s%n",
                stats.latencySamples(), stats.latencyPercentileNanos(50) / 1000, stats.latencyPercentileNanos(99) / 1000,
                stats.maxLatencyNanos() / 1000, stats.maxTickNanos() / 1000, stats.overruns(), stats.maxOverrunNanos() / 1000, yes(stats.schedFifo()),
                yes(stats.memoryLocked()), yes(stats.dmaLatencyHeld()));
        if (cyclic == null) {
            return 1;
        }
        System.out.printf(Locale.ROOT, "baseline cyclictest: %d wake-ups, p50 %d µs, p99 %d µs, max %d µs%n", cyclic[3],
                cyclic[0], cyclic[1], cyclic[2]);
        double ratio = (stats.latencyPercentileNanos(99) / 1000.0) / Math.max(1, cyclic[1]);
        boolean overrunsOk = stats.maxOverrunNanos() <= 1_000_000;
        System.out.printf(Locale.ROOT, "p99 ratio %.2f× cyclictest (target ≤ 1.25: %s); no overrun over 1 ms: %s%n", ratio,
                ratio <= 1.25 ? "met" : "NOT met", overrunsOk ? "met" : "NOT met");
        return 0;
    }

    private static String yes(boolean b) {
        return b ? "yes" : "no";
    }

    /** Runs cyclictest with a 1 µs histogram; returns {p50, p99, max, samples} in µs, or null (message printed). */
    private long[] cyclictest() throws IOException, InterruptedException {
        List<String> cmd = List.of("cyclictest", "-m", "-p" + priority, "-i1000", "-t1", "-q", "-h2000",
                "-D" + seconds);
        Process p;
        try {
            p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        } catch (IOException e) {
            System.err.println("fdnet bench rt: cyclictest is missing (Debian rt-tests): apt-get install -y rt-tests");
            return null;
        }
        long[] histogram = new long[2001];
        long max = 0;
        List<String> other = new ArrayList<>();
        try (BufferedReader in = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                String t = line.trim();
                if (t.matches("\\d+\\s+\\d+")) {
                    String[] f = t.split("\\s+");
                    int bin = Integer.parseInt(f[0]);
                    if (bin < histogram.length) {
                        histogram[bin] += Long.parseLong(f[1]);
                    }
                } else if (t.startsWith("# Max Latencies:")) {
                    max = Long.parseLong(t.substring("# Max Latencies:".length()).trim().split("\\s+")[0]);
                } else if (t.startsWith("# Histogram Overflows:")) {
                    histogram[2000] += Long.parseLong(t.substring("# Histogram Overflows:".length()).trim().split("\\s+")[0]);
                } else if (!t.startsWith("#") && !t.isEmpty()) {
                    other.add(t);
                }
            }
        }
        if (!p.waitFor(seconds + 30L, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            System.err.println("fdnet bench rt: cyclictest did not end; killed it");
            return null;
        }
        long total = 0;
        for (long c : histogram) {
            total += c;
        }
        if (p.exitValue() != 0 || total == 0) {
            System.err.println("fdnet bench rt: cyclictest failed (exit " + p.exitValue() + "): " + String.join(" | ", other));
            return null;
        }
        // Same convention as LoopStatistics: the upper edge of the 1 µs bin holding the percentile.
        return new long[] {percentile(histogram, total, 50), percentile(histogram, total, 99), max, total};
    }

    private static long percentile(long[] histogram, long total, double pct) {
        long rank = (long) Math.ceil(pct / 100 * total);
        long seen = 0;
        for (int i = 0; i < histogram.length; i++) {
            seen += histogram[i];
            if (seen >= rank) {
                return i + 1;
            }
        }
        return histogram.length;
    }
}
