package org.fdnet.roq.cli;

import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;
import org.fdnet.event.client.ClientStatus;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.roq.bridge.SimBridge;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.JointCommand;
import org.fdnet.roq.sim.LoopStatistics;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SharedBlockLayout;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.runtime.RuntimeNetwork;
import org.fdnet.runtime.RuntimeOptions;

/**
 * {@code fdnet bench roq} part (b): reflex latency in real time. The loop counts, for every command it applies, the
 * ticks from the snapshot the command was based on ({@link JointCommand#basedOnTick}) to the first snapshot computed
 * under it ({@link LoopStatistics#reflexPercentileTicks}); 1 tick = 1 ms, so "1" means applied at the very next
 * tick. Measured for a bare Java echo (a thread that copies each new snapshot's tick into the command slot, no
 * network: the baseline) and then for the network joined by the real-time {@link SimBridge}, recording with a
 * logger, each for the same number of wall seconds, one after the other in the same run.
 */
final class ReflexLatencyBench {
    private final Course course;
    private final NetworkInfo definition;
    private final Path network;
    private final int seconds;
    private final boolean record;

    ReflexLatencyBench(Course course, NetworkInfo definition, Path network, int seconds, boolean record) {
        this.course = course;
        this.definition = definition;
        this.network = network;
        this.seconds = seconds;
        this.record = record;
    }

    int run() throws Exception {
        System.out.printf(Locale.ROOT, "fdnet bench roq (b): reflex latency in real time, %d wall s each, course %s%n",
                seconds, course.name());
        LoopStatistics echo = echoAlone();
        print("baseline: bare Java echo       ", echo, "");
        NetworkStateLogger logger = null;
        if (record) {
            try {
                logger = LocalLogger.start();
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
            LoopStatistics withNetwork = withNetwork(client);
            String recorded = "";
            if (client != null) {
                client.close();
                ClientStatus st = client.status();
                recorded = String.format(Locale.ROOT, " (logger recording: %,d of %,d events committed, %,d lost)",
                        st.acked(), st.accepted(), st.lost());
            }
            print("network " + network.getFileName() + " + bridge", withNetwork, recorded);
            int p99 = withNetwork.reflexPercentileTicks(99);
            System.out.printf(Locale.ROOT, "network reflex p99 %d ms (target ≤ 2 ms: %s); echo baseline p99 %d ms%n",
                    p99, p99 <= 2 ? "met" : "NOT met", echo.reflexPercentileTicks(99));
        } finally {
            if (logger != null) {
                logger.stop();
            }
        }
        return 0;
    }

    private LoopStatistics echoAlone() throws InterruptedException {
        LoopStatistics stats = new LoopStatistics();
        try (RoqSimulator sim = RoqSimulator.open(course, SimMode.REAL_TIME)) {
            SensorSnapshot s = new SensorSnapshot();
            JointCommand command = new JointCommand();
            sim.read(s);
            for (int j = 0; j < RoqGeometry.JOINTS; j++) {
                command.target(j, s.jointAngle(j));
            }
            long end = System.nanoTime() + seconds * 1_000_000_000L;
            long last = -1;
            while (System.nanoTime() < end) {
                long tick = sim.read(s);
                if (tick == last) {
                    LockSupport.parkNanos(50_000); // the bridge's own polling period
                    continue;
                }
                last = tick;
                command.basedOnTick(tick);
                sim.send(command);
            }
            sim.statistics(stats);
        }
        return stats;
    }

    private LoopStatistics withNetwork(LoggerClient client) throws Exception {
        LoopStatistics stats = new LoopStatistics();
        RuntimeOptions options = RuntimeOptions.defaults();
        if (client != null) {
            options = options.sink(client);
        }
        try (RoqSimulator sim = RoqSimulator.open(course, SimMode.REAL_TIME);
             RuntimeNetwork net = RuntimeNetwork.start(definition, options);
             SimBridge bridge = SimBridge.realTime(net, sim)) {
            for (int second = 1; second <= seconds; second++) {
                Thread.sleep(1000);
                if (second % 10 == 0 || second == seconds) {
                    sim.statistics(stats);
                    System.out.printf(Locale.ROOT, "  %3d s: %,d commands applied, reflex p50 %d ms p99 %d ms%n", second,
                            stats.commandsApplied(), stats.reflexPercentileTicks(50), stats.reflexPercentileTicks(99));
                }
            }
            sim.statistics(stats);
        }
        return stats;
    }

    private static void print(String what, LoopStatistics s, String suffix) {
        StringBuilder bins = new StringBuilder();
        for (int t = 0; t < SharedBlockLayout.REFLEX_BINS; t++) {
            if (s.reflexCount(t) > 0) {
                bins.append(String.format(Locale.ROOT, " %s%d:%,d", t == SharedBlockLayout.REFLEX_BINS - 1 ? "≥" : "", t,
                        s.reflexCount(t)));
            }
        }
        System.out.printf(Locale.ROOT, "%s reflex p50 %d ms, p99 %d ms over %,d commands applied (%,d stale); loop"
                        + " wake-up p99 %.1f µs, %,d overruns of %,d ticks; by ticks:%s%s%n", what,
                s.reflexPercentileTicks(50), s.reflexPercentileTicks(99), s.commandsApplied(), s.commandsStale(),
                s.latencyPercentileNanos(99) / 1e3, s.overruns(), s.ticks(), bins, suffix);
    }
}
