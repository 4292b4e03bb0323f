package org.fdnet.roq.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.LongAdder;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.client.ClientStatus;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerConfigFile;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.bridge.SimBridge;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.CourseFormatException;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.LoopStatistics;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.roq.sim.SimOptions;
import org.fdnet.roq.view.RoqScreenshot;
import org.fdnet.runtime.RuntimeNetwork;
import org.fdnet.runtime.RuntimeOptions;
import org.fdnet.runtime.RuntimeStartException;
import org.fdnet.runtime.Value;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fdnet demo}: a RoQ network (default networks/roq-walk.fdn) on the real-time simulator, joined by the
 * real-time {@link SimBridge}; a progress line each second and a summary at the end. With {@code --logger}
 * every event also goes to a running {@code fdnet logger}.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = "RoQ walking on the real-time simulator under an FDNet network, with a progress line each second.")
public final class DemoCommand implements Callable<Integer> {
    @Option(names = "--for", defaultValue = "30", paramLabel = "SECONDS", description = "how long to run, s (default 30)")
    int seconds;

    @Option(names = "--course", defaultValue = "flat", description = "course: flat, slope, rubble, fragile or a file (default flat)")
    String course;

    @Option(names = "--seed", defaultValue = "1", description = "seed of the sensors' noise (default 1)")
    long seed;

    @Option(names = "--network", defaultValue = "networks/roq-walk.fdn", description = "network (default networks/roq-walk.fdn)")
    Path network;

    @Option(names = "--logger", paramLabel = "HOST:PORT",
            description = "record with a running network state logger at HOST:PORT (default: start one here, with its"
                    + " embedded PostgreSQL)")
    String logger;

    @Option(names = "--no-logger", description = "record nothing (count the events only)")
    boolean noLogger;

    @Option(names = "--screenshot", paramLabel = "FILE",
            description = "at the end, render the robot and the terrain (top and side views) to this PNG")
    Path screenshot;

    @Override
    public Integer call() throws Exception {
        if (seconds < 1) {
            System.err.println("fdnet demo: --for must be at least 1 s, was " + seconds);
            return 2;
        }
        Course c;
        NetworkInfo definition;
        try {
            c = CourseLoader.resolve(course);
            if (!Files.isRegularFile(network)) {
                System.err.println("fdnet demo: no network file " + network.toAbsolutePath());
                return 2;
            }
            definition = NetworkRepository.load(network);
        } catch (CourseFormatException | NetworkFileException e) {
            System.err.println("fdnet demo: " + e.getMessage());
            return 2;
        }
        if (noLogger && logger != null) {
            System.err.println("fdnet demo: --logger and --no-logger exclude each other");
            return 2;
        }
        NetworkStateLogger embedded = null;
        if (!noLogger && logger == null) {
            System.out.println("fdnet demo: starting the network state logger (embedded PostgreSQL) ...");
            try {
                LoggerConfig config = LoggerConfigFile.load(LoggerConfigFile.defaultPath());
                config.set(LoggerSetting.RECEIVER_PORT, "0").set(LoggerSetting.SENDER_PORT, "0");
                embedded = new NetworkStateLogger(config);
                embedded.start();
            } catch (Exception e) {
                System.err.println("fdnet demo: the logger does not start: " + e.getMessage()
                        + " (run with --no-logger to do without)");
                if (embedded != null) {
                    embedded.close();
                }
                return 1;
            }
            logger = "127.0.0.1:" + embedded.receiverPort();
        }
        try {
            return run(embedded);
        } finally {
            if (embedded != null) {
                embedded.stop();
            }
        }
    }

    private int run(NetworkStateLogger embedded) throws Exception {
        Course c = CourseLoader.resolve(course);
        NetworkInfo definition = NetworkRepository.load(network);
        LoggerClient client = null;
        if (logger != null) {
            try {
                client = new LoggerClient(LoggerClientSettings.parseAddress(logger, "fdnet demo " + definition.name()));
            } catch (IllegalArgumentException e) {
                System.err.println("fdnet demo: --logger " + logger + ": " + e.getMessage());
                return 2;
            }
        }
        LongAdder events = new LongAdder();
        LoggerClient recording = client;
        EventSink counter = new EventSink() {
            @Override
            public void accept(NetworkEvent event) {
                events.increment();
                if (recording != null) {
                    recording.accept(event);
                }
            }

            @Override
            public void flush() {
                if (recording != null) {
                    recording.flush();
                }
            }
        };
        SimOptions simOptions = new SimOptions(SimMode.REAL_TIME, SimOptions.DEFAULT_PRIORITY, true, seed, 0.0);
        SensorSnapshot s = new SensorSnapshot();
        LoopStatistics stats = new LoopStatistics();
        double startX;
        double startY;
        boolean fallen = false;
        try (RoqSimulator sim = RoqSimulator.open(c, simOptions);
             RuntimeNetwork net = RuntimeNetwork.start(definition, RuntimeOptions.defaults().sink(counter));
             SimBridge bridge = SimBridge.realTime(net, sim)) {
            sim.read(s);
            startX = s.groundTruthBodyPosition(0);
            startY = s.groundTruthBodyPosition(1);
            System.out.printf(Locale.ROOT, "fdnet demo: %s on course %s, real time, %d s%s%n", network, c.name(), seconds,
                    client == null ? ", not recorded" : ", recording with the logger at " + logger + " (run " + client.run() + ")");
            for (int second = 1; second <= seconds; second++) {
                Thread.sleep(1000);
                sim.read(s);
                fallen = isFallen(net);
                System.out.printf(Locale.ROOT, "  t=%5.1f s  distance %.3f m  height %.3f m  roll %+.3f  pitch %+.3f  broken cells %d"
                                + "  events %,d%s%n", s.simTime(), s.groundTruthBodyPosition(0) - startX,
                        s.groundTruthBodyPosition(2), s.roll(), s.pitch(), s.brokenCellCount(), events.sum(),
                        fallen ? "  FALLEN" : "");
            }
            sim.statistics(stats);
            if (screenshot != null) {
                RoqScreenshot.write(s, sim.heightfield(), 1200, 700, screenshot);
                System.out.println("screenshot: " + screenshot.toAbsolutePath());
            }
        } catch (RuntimeStartException e) {
            System.err.println("fdnet demo: " + network + " does not start: " + e.getMessage());
            return 1;
        }
        System.out.printf(Locale.ROOT, "summary: walked %.3f m forward (%.3f m sideways) in %.1f s; %s; broken cells %d%n",
                s.groundTruthBodyPosition(0) - startX, s.groundTruthBodyPosition(1) - startY, s.simTime(),
                fallen ? "FELL" : "no fall", s.brokenCellCount());
        System.out.printf(Locale.ROOT, "loop: %,d ticks, %,d overruns, wake-up p99 %.1f µs (max %.1f µs)%n", stats.ticks(),
                stats.overruns(), stats.latencyPercentileNanos(99) / 1e3, stats.maxLatencyNanos() / 1e3);
        System.out.printf(Locale.ROOT, "events: %,d logged by the network%n", events.sum());
        if (client != null) {
            client.close();
            ClientStatus st = client.status();
            System.out.printf(Locale.ROOT, "logger: %,d of %,d events of run %s committed to %s, %,d lost%n",
                    st.acked(), st.accepted(), client.run(),
                    embedded != null ? "the embedded PostgreSQL" : "the logger at " + logger, st.lost());
        }
        return fallen ? 1 : 0;
    }

    private static boolean isFallen(RuntimeNetwork net) {
        try {
            Value v = net.controller().value(NodeRef.parse("fallen", "main"));
            return v != null && v.asBoolean();
        } catch (IllegalArgumentException e) {
            return false;
        }
    }
}
