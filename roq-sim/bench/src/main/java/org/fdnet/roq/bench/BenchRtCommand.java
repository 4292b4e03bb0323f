package org.fdnet.roq.bench;

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
import org.fdnet.roq.sim.SharedBlockLayout;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.roq.sim.SimOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fdnet bench rt}: the real-time joint loop's wake-up latency and overruns while Java reads snapshots and
 * sends commands at 100 Hz, beside {@code cyclictest} (Debian rt-tests) with the same interval (1000 µs),
 * priority and memory locking: the best this machine's kernel gives any 1 kHz thread. The two alternate in rounds
 * of 10 s so the machine's changing load falls on both alike; histograms are summed over the rounds.
 */
@Command(name = "rt", mixinStandardHelpOptions = true,
        description = "Real-time loop wake-up latency and overruns beside cyclictest (same interval and priority, "
                + "same run, alternating rounds of 10 s).")
public final class BenchRtCommand implements Callable<Integer> {
    private static final int ROUND_SECONDS = 10;
    private static final int BINS = SharedBlockLayout.HISTOGRAM_BINS;

    @Option(names = "--seconds", defaultValue = "60", description = "seconds of the loop and as many of cyclictest (default 60)")
    int seconds;

    @Option(names = "--priority", defaultValue = "80", description = "SCHED_FIFO priority of both (default 80)")
    int priority;

    private final long[] loopHistogram = new long[BINS];
    private long loopMax;
    private long overruns;
    private long worstOverrun;
    private long longestTick;
    private String realtime = "";
    private final long[] cyclicHistogram = new long[BINS];
    private long cyclicMax;

    @Override
    public Integer call() throws Exception {
        if (seconds < 1) {
            System.err.println("fdnet bench rt: --seconds must be at least 1");
            return 2;
        }
        System.out.printf(Locale.ROOT, "fdnet bench rt: %d s of the joint loop (1 kHz, SCHED_FIFO %d) and %d s of "
                + "cyclictest -m -p%d -i1000, alternating in rounds of %d s%n", seconds, priority, seconds, priority,
                Math.min(ROUND_SECONDS, seconds));
        for (int done = 0; done < seconds; done += ROUND_SECONDS) {
            int length = Math.min(ROUND_SECONDS, seconds - done);
            runLoop(length);
            if (!runCyclictest(length)) {
                return 1;
            }
            System.out.printf(Locale.ROOT, "  %3d s: loop p99 %d µs max %d µs overruns %d | cyclictest p99 %d µs max %d µs%n",
                    done + length, percentile(loopHistogram, 99), loopMax / 1000, overruns, percentile(cyclicHistogram, 99),
                    cyclicMax);
        }
        System.out.printf(Locale.ROOT, "roq-sim joint loop: %d wake-ups, p50 %d µs, p99 %d µs, max %d µs; longest tick %d µs; "
                        + "overruns %d (worst %d µs past the next deadline); %s%n",
                total(loopHistogram), percentile(loopHistogram, 50), percentile(loopHistogram, 99), loopMax / 1000,
                longestTick / 1000, overruns, worstOverrun / 1000, realtime);
        System.out.printf(Locale.ROOT, "baseline cyclictest: %d wake-ups, p50 %d µs, p99 %d µs, max %d µs%n",
                total(cyclicHistogram), percentile(cyclicHistogram, 50), percentile(cyclicHistogram, 99), cyclicMax);
        double ratio = (double) percentile(loopHistogram, 99) / Math.max(1, percentile(cyclicHistogram, 99));
        boolean overrunsOk = worstOverrun <= 1_000_000;
        System.out.printf(Locale.ROOT, "p99 ratio %.2f× cyclictest (target ≤ 1.25: %s); no overrun over 1 ms: %s%n", ratio,
                ratio <= 1.25 ? "met" : "NOT met", overrunsOk ? "met" : "NOT met");
        return 0;
    }

    /** One round of the loop with Java reading and commanding at 100 Hz; adds its figures to the totals. */
    private void runLoop(int length) throws InterruptedException {
        LoopStatistics stats = new LoopStatistics();
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimOptions.of(SimMode.REAL_TIME).withPriority(priority))) {
            SensorSnapshot s = new SensorSnapshot();
            JointCommand command = new JointCommand();
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(length);
            while (System.nanoTime() < end) {
                Thread.sleep(10);
                sim.read(s);
                command.basedOnTick(s.tick()).target(0, 0.1 * Math.sin(s.simTime()));
                sim.send(command);
            }
            sim.statistics(stats);
        }
        for (int i = 0; i < BINS; i++) {
            loopHistogram[i] += stats.latencyCount(i);
        }
        loopMax = Math.max(loopMax, stats.maxLatencyNanos());
        overruns += stats.overruns();
        worstOverrun = Math.max(worstOverrun, stats.maxOverrunNanos());
        longestTick = Math.max(longestTick, stats.maxTickNanos());
        realtime = "SCHED_FIFO " + yes(stats.schedFifo()) + ", mlockall " + yes(stats.memoryLocked())
                + ", cpu_dma_latency " + yes(stats.dmaLatencyHeld());
    }

    private static String yes(boolean b) {
        return b ? "yes" : "no";
    }

    /** One round of cyclictest with a 1 µs histogram; adds it to the totals. False (message printed) on failure. */
    private boolean runCyclictest(int length) throws IOException, InterruptedException {
        List<String> cmd = List.of("cyclictest", "-m", "-p" + priority, "-i1000", "-t1", "-q", "-h" + BINS, "-D" + length);
        Process p;
        try {
            p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        } catch (IOException e) {
            System.err.println("fdnet bench rt: cyclictest is missing (Debian rt-tests): apt-get install -y rt-tests");
            return false;
        }
        long[] round = new long[BINS];
        List<String> other = new ArrayList<>();
        try (BufferedReader in = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                String t = line.trim();
                if (t.matches("\\d+\\s+\\d+")) {
                    String[] f = t.split("\\s+");
                    int bin = Integer.parseInt(f[0]);
                    round[Math.min(bin, BINS - 1)] += Long.parseLong(f[1]);
                } else if (t.startsWith("# Max Latencies:")) {
                    cyclicMax = Math.max(cyclicMax, firstNumber(t, "# Max Latencies:"));
                } else if (t.startsWith("# Histogram Overflows:")) {
                    round[BINS - 1] += firstNumber(t, "# Histogram Overflows:");
                } else if (!t.startsWith("#") && !t.isEmpty()) {
                    other.add(t);
                }
            }
        }
        if (!p.waitFor(length + 30L, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            System.err.println("fdnet bench rt: cyclictest did not end; killed it");
            return false;
        }
        if (p.exitValue() != 0 || total(round) == 0) {
            System.err.println("fdnet bench rt: cyclictest failed (exit " + p.exitValue() + "): " + String.join(" | ", other));
            return false;
        }
        for (int i = 0; i < BINS; i++) {
            cyclicHistogram[i] += round[i];
        }
        return true;
    }

    private static long firstNumber(String line, String prefix) {
        return Long.parseLong(line.substring(prefix.length()).trim().split("\\s+")[0]);
    }

    private static long total(long[] histogram) {
        long n = 0;
        for (long c : histogram) {
            n += c;
        }
        return n;
    }

    /** The upper edge, µs, of the 1 µs bin holding the percentile (LoopStatistics' convention), for both. */
    private static long percentile(long[] histogram, double pct) {
        long rank = (long) Math.ceil(pct / 100 * total(histogram));
        long seen = 0;
        for (int i = 0; i < histogram.length; i++) {
            seen += histogram[i];
            if (seen >= rank && rank > 0) {
                return i + 1;
            }
        }
        return 0;
    }
}
