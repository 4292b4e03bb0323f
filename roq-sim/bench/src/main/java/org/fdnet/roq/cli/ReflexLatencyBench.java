package org.fdnet.roq.cli;

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
    private final int seconds;
    private final int drops;
    private final boolean record;

    ReflexLatencyBench(Course course, NetworkInfo definition, Path network, int seconds, int drops, boolean record) {
        this.course = course;
        this.definition = definition;
        this.network = network;
        this.seconds = seconds;
        this.drops = drops;
        this.record = record;
    }

    int run() throws Exception {
        System.out.printf(Locale.ROOT, "fdnet bench roq (b): snapshot-to-applied-command latency in real time, %d wall s"
                + " each, course %s, network %s; pushes of %.0f N for %.1f s towards the swinging leg's corner; %d"
                + " sole-force drops (the cell under the front-left foot breaks while hind-right swings)%n",
                seconds, course.name(), network, StimulusLatencyRun.PUSH_NEWTONS, StimulusLatencyRun.PUSH_SECONDS,
                drops);
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
            StimulusLatencyRun reflexRun = new StimulusLatencyRun(course, definition, true, seconds, drops, client);
            StimulusLatencyRun periodicRun = new StimulusLatencyRun(course, definition, false, seconds, drops, client);
            StimulusLatencyRun.Outcome reflex = reflexRun.run(StimulusLatencyRun.Kind.PUSH);
            print("tilt reflex, pushes, " + reflexRun.describe(), reflex);
            StimulusLatencyRun.Outcome reflexDrops = reflexRun.run(StimulusLatencyRun.Kind.CELL_BREAK);
            print("tilt reflex, sole-force drops, " + reflexRun.describe(), reflexDrops);
            StimulusLatencyRun.Outcome periodic = periodicRun.run(StimulusLatencyRun.Kind.PUSH);
            print("periodic path, pushes, " + periodicRun.describe(), periodic);
            reflexDrops.latencies().addAllTo(reflex.latencies());
            String recorded = "not recorded";
            if (client != null) {
                client.close();
                ClientStatus st = client.status();
                recorded = String.format(Locale.ROOT, "logger recording: %,d of %,d events committed, %,d lost",
                        st.acked(), st.accepted(), st.lost());
            }
            LatencySample r = reflex.latencies();
            String verdict = r.count() == 0 ? "NOT met (no command answered a stimulus)"
                    : r.percentile(99) <= 2 ? "met" : "NOT met";
            System.out.printf(Locale.ROOT, "tilt reflex (pushes and drops) p99 %s (target ≤ 2 ms: %s; %s); periodic path p99 %s; echo"
                            + " baseline p99 %d ms%n", r.count() == 0 ? "-" : r.percentile(99) + " ms", verdict, recorded,
                    periodic.latencies().count() == 0 ? "- (no command computed from the stimulus)"
                            : periodic.latencies().percentile(99) + " ms", echo.percentile(99));
        } finally {
            if (logger != null) {
                logger.close();
            }
        }
        return 0;
    }

    private static void print(String what, StimulusLatencyRun.Outcome o) {
        System.out.printf(Locale.ROOT, "%s: %d stimuli, %d shown beyond the thresholds, %d answered by a command: %s%s%n",
                what, o.stimuli(), o.shown(), o.latencies().count(), o.latencies().summary(),
                o.fell() ? " (RoQ fell: pushes stopped)" : "");
    }

    private LatencySample echoAlone() {
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
            long end = System.nanoTime() + seconds * 1_000_000_000L;
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
