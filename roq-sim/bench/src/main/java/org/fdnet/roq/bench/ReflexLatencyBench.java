package org.fdnet.roq.bench;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;
import org.fdnet.event.client.ClientStatus;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.logger.InProcessLogger;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.JointCommand;
import org.fdnet.roq.sim.LoopStatistics;
import org.fdnet.roq.sim.RealTimeThreads;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;

/**
 * {@code fdnet bench roq} part (b): reflex latency through the network, in real time, from stimuli. Three
 * measurements, one after the other in the same run:
 * <ol>
 *   <li>baseline: a bare Java echo, no network — each new snapshot's tick copied into a command at once;</li>
 *   <li>the tilt reflex: the network (default {@code networks/roq-reflex-bench.fdn}) walking with the
 *   {@link org.fdnet.roq.bridge.SimBridge}, recording with a logger, pushed during leg swings
 *   ({@link StimulusLatencyRun});</li>
 *   <li>the periodic path: the same with the reflex's module unloaded, so only what the rest of the network
 *   computes from the sensors can answer.</li>
 * </ol>
 * Each latency is from the snapshot that first showed the stimulus (for the echo: every snapshot) to the tick the
 * loop applied the first command computed from it, + 1 (the tick it first shows in a snapshot): 1 ms = the very
 * next tick. The figures come from the loop's applied-command ring (applied tick and source tick per command).
 */
final class ReflexLatencyBench {
    private final Course course;
    private final NetworkInfo definition;
    private final Path network;
    private final int echoSeconds;
    private final int pushes;
    private final int drops;
    private final boolean record;
    private final boolean trace;

    ReflexLatencyBench(Course course, NetworkInfo definition, Path network, int echoSeconds, int pushes, int drops,
                       boolean record, boolean trace) {
        this.trace = trace;
        this.course = course;
        this.definition = definition;
        this.network = network;
        this.echoSeconds = echoSeconds;
        this.pushes = pushes;
        this.drops = drops;
        this.record = record;
    }

    int run() throws Exception {
        System.out.printf(Locale.ROOT, "fdnet bench roq (b): snapshot-to-applied-command latency in real time, course %s,"
                + " network %s; %d pushes of %.0f N for %.1f s towards the swinging leg's corner (reflex loaded, then"
                + " unloaded); %d sole-force drops (the cell under the front-left foot breaks while hind-right swings);"
                + " echo %d s; load average at start %s%n", course.name(), network, pushes,
                StimulusLatencyRun.PUSH_NEWTONS, StimulusLatencyRun.PUSH_SECONDS, drops, echoSeconds, loadAverage());
        LatencySample echo = echoAlone();
        System.out.printf(Locale.ROOT, "baseline: bare Java echo, every snapshot: %s commands%n", echo.summary());
        InProcessLogger logger = null;
        if (record) {
            try {
                logger = InProcessLogger.ofUserConfig(false);
            } catch (Exception e) {
                System.err.println("fdnet bench roq: the logger does not start: " + e.getMessage()
                        + " (run with --no-logger to do without)");
                return 1;
            }
        }
        try {
            LoggerClient client = logger == null ? null
                    : new LoggerClient(LoggerClientSettings.parseAddress("127.0.0.1:" + logger.receiverPort(),
                            "fdnet bench roq " + definition.name()));
            StimulusLatencyRun reflexRun = new StimulusLatencyRun(course, definition, true, pushes, drops, client, trace);
            StimulusLatencyRun periodicRun = new StimulusLatencyRun(course, definition, false, pushes, drops, client, trace);
            StimulusLatencyRun.Outcome reflex = reflexRun.run(StimulusLatencyRun.Kind.PUSH);
            print("tilt reflex, pushes, " + reflexRun.describe(), reflex);
            StimulusLatencyRun.Outcome reflexDrops = reflexRun.run(StimulusLatencyRun.Kind.CELL_BREAK);
            print("tilt reflex, sole-force drops, " + reflexRun.describe(), reflexDrops);
            StimulusLatencyRun.Outcome periodic = periodicRun.run(StimulusLatencyRun.Kind.PUSH);
            print("periodic path, pushes, " + periodicRun.describe(), periodic);
            LatencySample r = new LatencySample();
            reflex.latencies().addAllTo(r);
            reflexDrops.latencies().addAllTo(r);
            String recorded = "not recorded";
            if (client != null) {
                client.close();
                ClientStatus st = client.status();
                recorded = String.format(Locale.ROOT, "logger recording: %,d of %,d events committed, %,d lost",
                        st.acked(), st.accepted(), st.lost());
            }
            String verdict = r.count() == 0 ? "NOT met (no command answered a stimulus)"
                    : r.percentile(99) <= 2 ? "met" : "NOT met";
            System.out.printf(Locale.ROOT, "tilt reflex p99: pushes %s, drops %s, both together %s over %d (target ≤ 2 ms:"
                            + " %s; %s); periodic path p99 %s; echo baseline p99 %d ms; load average at end %s%n",
                    p99(reflex.latencies()), p99(reflexDrops.latencies()), p99(r), r.count(), verdict, recorded,
                    periodic.latencies().count() == 0 ? "- (no command computed from the stimulus)"
                            : p99(periodic.latencies()), echo.percentile(99), loadAverage());
        } finally {
            if (logger != null) {
                logger.close();
            }
        }
        return 0;
    }

    private static String p99(LatencySample s) {
        return s.count() == 0 ? "-" : s.percentile(99) + " ms";
    }

    /** The 1, 5 and 15 minute load averages ({@code /proc/loadavg}), or the JVM's 1 minute figure elsewhere. */
    static String loadAverage() {
        try {
            String[] f = Files.readString(Path.of("/proc/loadavg")).trim().split("\\s+");
            return f[0] + " " + f[1] + " " + f[2];
        } catch (IOException | RuntimeException e) {
            return String.format(Locale.ROOT, "%.2f", ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        }
    }

    private static void print(String what, StimulusLatencyRun.Outcome o) {
        System.out.printf(Locale.ROOT, "%s: %d stimuli, %d shown beyond the thresholds, %d answered by a command: %s%s%n",
                what, o.stimuli(), o.shown(), o.latencies().count(), o.latencies().summary(),
                o.fell() ? " (RoQ fell: pushes stopped)" : "");
        o.traces().forEach(System.out::println);
    }

    /** On a thread of its own, promoted like the bridge's ({@link RealTimeThreads}), so the baseline is like for like. */
    private LatencySample echoAlone() throws InterruptedException {
        LatencySample[] sample = new LatencySample[1];
        RuntimeException[] failure = new RuntimeException[1];
        Thread echo = new Thread(() -> {
            try {
                RealTimeThreads.promoteCurrentThread();
                sample[0] = echoHere();
            } catch (RuntimeException e) {
                failure[0] = e;
            }
        }, "roq-echo");
        echo.start();
        echo.join();
        if (failure[0] != null) {
            throw new IllegalStateException("the echo baseline failed: " + failure[0].getMessage(), failure[0]);
        }
        return sample[0];
    }

    private LatencySample echoHere() {
        LatencySample sample = new LatencySample();
        long[] applied = new long[64];
        long[] source = new long[64];
        try (RoqSimulator sim = RoqSimulator.open(course, SimMode.REAL_TIME)) {
            SensorSnapshot s = new SensorSnapshot();
            JointCommand command = new JointCommand();
            sim.read(s);
            for (int j = 0; j < RoqGeometry.JOINTS; j++) {
                command.target(j, s.jointAngle(j));
            }
            long end = System.nanoTime() + echoSeconds * 1_000_000_000L;
            long last = -1;
            long seen = sim.appliedCommands(0, applied, source);
            while (System.nanoTime() < end) {
                long tick = sim.read(s);
                long count = sim.appliedCommands(seen, applied, source);
                for (long n = Math.max(seen, count - applied.length); n < count; n++) {
                    int i = (int) (n - Math.max(seen, count - applied.length));
                    sample.add(applied[i] + 1 - source[i]);
                }
                seen = count;
                if (tick == last) {
                    LockSupport.parkNanos(50_000); // the bridge's own polling period
                    continue;
                }
                last = tick;
                command.basedOnTick(tick);
                sim.send(command);
            }
            sim.statistics(new LoopStatistics());
        }
        return sample;
    }
}
