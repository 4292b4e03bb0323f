package org.fdnet.roq.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.Callable;
import javax.swing.SwingUtilities;
import org.fdnet.control.LocalLiveNetwork;
import org.fdnet.corba.cli.ControlOptions;
import org.fdnet.corba.control.ControlPublication;
import org.fdnet.event.client.ClientStatus;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.logger.InProcessLogger;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.bridge.CourseMeter;
import org.fdnet.roq.bridge.SimBridge;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.CourseFormatException;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.LoopStatistics;
import org.fdnet.roq.sim.RealTimeThreads;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.roq.sim.SimOptions;
import org.fdnet.roq.view.DemoFigures;
import org.fdnet.roq.view.RoqDemoPanel;
import org.fdnet.roq.view.RoqDemoWindow;
import org.fdnet.run.NetworkRun;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.cli.DurationText;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.engine.RuntimeStartException;
import org.fdnet.tls.TlsOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code fdnet demo}: a RoQ network (default networks/roq-rubble.fdn on the crossing course) on the real-time simulator, joined by the
 * real-time {@link SimBridge}; a progress line each second and a summary at the end, with the figures a
 * {@link DemoMeter} reads from the network (stability margin, probes, fragile cells). {@code --gui} shows it live in
 * a {@link RoqDemoWindow}; {@code --screenshot} renders that window's content to a PNG. With {@code --logger}
 * every event also goes to a running {@code fdnet logger}.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = "RoQ walking on the real-time simulator under an FDNet network, with a progress line each second.")
public final class DemoCommand implements Callable<Integer> {
    /** The window and the figures are refreshed this often; the progress line is printed each second. */
    private static final long FRAME_MILLIS = 100;
    /** The course is measured this often ({@link CourseMeter}: a break is told a probe's by the phase at that moment). */
    private static final long SAMPLE_MILLIS = 10;
    /** HoldCourse's own estimate of where RoQ is, shown beside the ground truth's figures when the network has it. */
    private static final NodeRef TRACK = new NodeRef("Course", "track");

    @Option(names = "--for", defaultValue = "100", paramLabel = "DURATION", converter = DurationText.class,
            description = "how long to run: 30s, 2m, or plain seconds (default 100: long enough to cross the"
                    + " crossing course's three bands of fragile cells)")
    Duration runFor;

    @Option(names = "--gui", description = "show the robot live in a window (top and side views, live figures)")
    boolean gui;

    @Option(names = "--course", defaultValue = "crossing", description = "course: flat, slope, rubble, fragile, crossing or a file (default crossing)")
    String course;

    @Option(names = "--seed", defaultValue = "1", description = "seed of the sensors' noise (default 1)")
    long seed;

    @Option(names = "--network", defaultValue = "networks/roq-rubble.fdn", description = "network (default networks/roq-rubble.fdn)")
    Path network;

    @Option(names = "--logger", paramLabel = "HOST:PORT",
            description = "record with a running network state logger at HOST:PORT (default: start one here, with its"
                    + " embedded PostgreSQL)")
    String logger;

    @Option(names = "--no-logger", description = "record nothing (count the events only)")
    boolean noLogger;

    @Option(names = "--screenshot", paramLabel = "FILE",
            description = "at the end, render the demo window (robot, terrain, path, live figures) to this PNG;"
                    + " works without --gui too (drawn off-screen)")
    Path screenshot;

    @Mixin
    ControlOptions control;

    @Mixin
    TlsOptions tls = new TlsOptions();

    /** HOST:PORT of the embedded logger's viewer service; null when the demo records with no logger of its own. */
    private String loggerViewer;

    /** The network's control object, for {@code fdnet control} and the editor's {@code --attach}; null without one. */
    private ControlPublication publishControl(RuntimeNetwork net, NetworkInfo definition) {
        try {
            return control.publish(new LocalLiveNetwork(NetworkRun.publishedName(definition, network), net.controller(),
                    java.util.Optional.ofNullable(loggerViewer)), new java.io.PrintWriter(System.out, true));
        } catch (IllegalArgumentException e) {
            System.err.println("fdnet demo: the control object is not published: " + e.getMessage());
            return null;
        }
    }

    @Override
    public Integer call() throws Exception {
        if (gui && java.awt.GraphicsEnvironment.isHeadless()) {
            System.err.println("fdnet demo: --gui needs a display and there is none ($DISPLAY is not set);"
                    + " --screenshot FILE without --gui draws the window off-screen");
            return 2;
        }
        if (runFor.toMillis() < 1000) {
            System.err.println("fdnet demo: --for must be at least 1 s, was " + runFor.toMillis() + " ms");
            return 2;
        }
        try { // as fdnet run: --tls, and no control object on a non-loopback address without it or --insecure
            tls.apply();
            if (!control.off()) {
                tls.requireSafeBind("the network's control object", control.host());
            }
        } catch (IllegalArgumentException | IllegalStateException e) {
            System.err.println("fdnet demo: " + e.getMessage());
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
        InProcessLogger embedded = null;
        if (!noLogger && logger == null) {
            System.out.println("fdnet demo: starting the network state logger (embedded PostgreSQL) ...");
            try {
                embedded = InProcessLogger.ofUserConfig(true);
            } catch (Exception e) {
                System.err.println("fdnet demo: the logger does not start: " + e.getMessage()
                        + " (run with --no-logger to do without)");
                return 1;
            }
            logger = "127.0.0.1:" + embedded.receiverPort();
            loggerViewer = embedded.viewerAddress();
        }
        try {
            return run(embedded);
        } finally {
            if (embedded != null) {
                embedded.close();
            }
        }
    }

    private int run(InProcessLogger embedded) throws Exception {
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
        DemoMeter meter = new DemoMeter(client);
        SimOptions simOptions = new SimOptions(SimMode.REAL_TIME, SimOptions.DEFAULT_PRIORITY, true, seed, 0.0);
        SensorSnapshot s = new SensorSnapshot();
        LoopStatistics stats = new LoopStatistics();
        long seconds = Math.max(1, runFor.toMillis() / 1000);
        double startX;
        double startY;
        boolean fallen = false;
        DemoFigures figures = DemoFigures.none();
        long snapshotsFed = 0;
        long longestFeedGapNanos = 0;
        long longestFeedGapTick = -1;
        CourseMeter onCourse = null;
        String sensedTrack = null;
        RoqDemoWindow window = null;
        try (RoqSimulator sim = RoqSimulator.open(c, simOptions);
             RuntimeNetwork net = RuntimeNetwork.start(definition, RuntimeOptions.defaults().sink(meter)
                     .workerStart(RealTimeThreads::promoteCurrentThread));
             SimBridge bridge = SimBridge.realTime(net, sim);
             ControlPublication published = publishControl(net, definition)) {
            meter.lookUpCounters(net);
            sim.read(s);
            startX = s.groundTruthBodyPosition(0);
            startY = s.groundTruthBodyPosition(1);
            System.out.printf(Locale.ROOT, "fdnet demo: %s on course %s, real time, %d s%s%n", network, c.name(), seconds,
                    client == null ? ", not recorded" : ", recording with the logger at " + logger + " (run " + client.run() + ")");
            if (embedded != null) {
                System.out.println(viewerLine(embedded, client));
            }
            if (gui) {
                window = RoqDemoWindow.open("FDNet demo: " + definition.name() + " on " + c.name(), sim.heightfield());
            }
            onCourse = new CourseMeter(s, c.fragileCells());
            long samples = runFor.toMillis() / SAMPLE_MILLIS;
            long t0 = System.nanoTime();
            for (long sample = 1; sample <= samples; sample++) {
                long due = t0 + sample * SAMPLE_MILLIS * 1_000_000L;
                long wait = due - System.nanoTime();
                if (wait > 0) {
                    Thread.sleep(wait / 1_000_000L, (int) (wait % 1_000_000L));
                }
                sim.read(s);
                onCourse.sample(s, net);
                if (sample % (FRAME_MILLIS / SAMPLE_MILLIS) != 0) {
                    continue;
                }
                long frame = sample / (FRAME_MILLIS / SAMPLE_MILLIS);
                sim.statistics(stats);
                fallen = isFallen(net);
                figures = meter.figures(net, s, startX, stats, fallen);
                if (window != null) {
                    if (!window.isShowing()) {
                        System.out.println("fdnet demo: the window was closed; stopping");
                        window = null;
                        break;
                    }
                    show(window, s, figures);
                }
                if (frame % (1000 / FRAME_MILLIS) == 0) {
                    System.out.println(figures.progressLine());
                }
            }
            sim.read(s);
            sim.statistics(stats);
            figures = meter.figures(net, s, startX, stats, fallen);
            sensedTrack = sensedTrack(net);
            snapshotsFed = bridge.cycles();
            longestFeedGapNanos = bridge.longestFeedGapNanos();
            longestFeedGapTick = bridge.longestFeedGapTick();
            if (screenshot != null) {
                writeScreenshot(window, s, figures, sim);
                System.out.println("screenshot: " + screenshot.toAbsolutePath());
            }
        } catch (RuntimeStartException e) {
            System.err.println("fdnet demo: " + network + " does not start: " + e.getMessage());
            return 1;
        } finally {
            if (window != null) {
                window.close();
            }
        }
        System.out.printf(Locale.ROOT, "summary: walked %.2f m in %.1f s, %s; crusts found by probes %d, loaded-foot"
                        + " breakthroughs %d (target: none); off the course line at most %.2f m, off the heading at most"
                        + " %.2f rad%n", s.groundTruthBodyPosition(0) - startX, s.simTime(), fallen ? "FELL" : "no fall",
                onCourse.probeBroken(), onCourse.loadedBreakthroughs(), onCourse.maxTrackError(),
                onCourse.maxHeadingError());
        System.out.printf(Locale.ROOT, "details: %.3f m sideways; smallest stability margin %s; probes %s; fragile cells"
                        + " found %s, avoided %s, broken %d%n", s.groundTruthBodyPosition(1) - startY,
                DemoFigures.metres(figures.smallestMargin()), DemoFigures.count(figures.probes()),
                DemoFigures.count(figures.fragileFound()), DemoFigures.count(figures.fragileAvoided()), s.brokenCellCount());
        System.out.println("course: " + onCourse.summary());
        if (sensedTrack != null) {
            System.out.println("course as the network sensed it (" + TRACK + "): " + sensedTrack);
        }
        System.out.printf(Locale.ROOT, "loop: %,d ticks, %,d overruns, wake-up p99 %.1f µs (max %.1f µs)%n", stats.ticks(),
                stats.overruns(), stats.latencyPercentileNanos(99) / 1e3, stats.maxLatencyNanos() / 1e3);
        System.out.printf(Locale.ROOT, "network: %,d snapshots fed, longest gap between two %.1f ms (until t=%.1f s)%n",
                snapshotsFed, longestFeedGapNanos / 1e6, longestFeedGapTick / 1e3);
        System.out.printf(Locale.ROOT, "events: %,d logged by the network%n", meter.events());
        if (client != null) {
            client.close();
            ClientStatus st = client.status();
            System.out.printf(Locale.ROOT, "logger: %,d of %,d events of run %s committed to %s, %,d lost%n",
                    st.acked(), st.accepted(), client.run(),
                    embedded != null ? "the embedded PostgreSQL" : "the logger at " + logger, st.lost());
        }
        return fallen ? 1 : 0;
    }

    /**
     * The one line telling where viewers reach the embedded logger and the logger's id of this run (what
     * {@code fdnet viewer --replay} takes), once the logger has opened the run (waits at most 3 s for that).
     */
    private String viewerLine(InProcessLogger embedded, LoggerClient client) throws InterruptedException {
        java.util.OptionalInt run = java.util.OptionalInt.empty();
        for (int i = 0; i < 60 && run.isEmpty(); i++) {
            run = embedded.logger().directory().runIdOf(client.run());
            if (run.isEmpty()) {
                Thread.sleep(50);
            }
        }
        return run.isPresent()
                ? "logger for viewers: " + loggerViewer + ", run " + run.getAsInt() + " (fdnet viewer --logger "
                        + loggerViewer + " --replay " + run.getAsInt() + " --from -60)"
                : "logger for viewers: " + loggerViewer + " (fdnet viewer --logger " + loggerViewer
                        + "; the run has not reached the logger yet)";
    }

    private static void show(RoqDemoWindow window, SensorSnapshot s, DemoFigures figures) {
        SensorSnapshot copy = new SensorSnapshot();
        copy.copyFrom(s);
        SwingUtilities.invokeLater(() -> window.panel().show(copy, figures));
    }

    /** The window's content as it is now; without --gui, the same panel laid out off-screen with the last figures. */
    private void writeScreenshot(RoqDemoWindow window, SensorSnapshot s, DemoFigures figures, RoqSimulator sim)
            throws Exception {
        Exception[] failed = new Exception[1];
        SwingUtilities.invokeAndWait(() -> {
            try {
                RoqDemoPanel panel = window != null ? window.panel() : new RoqDemoPanel(sim.heightfield());
                if (window == null) {
                    panel.show(s, figures);
                }
                panel.writePng(screenshot);
            } catch (IOException e) {
                failed[0] = e;
            }
        });
        if (failed[0] != null) {
            throw failed[0];
        }
    }

    /** HoldCourse's estimate {x, y, heading} from the start, or null when the network has no such Data. */
    private static String sensedTrack(RuntimeNetwork net) {
        try {
            Value v = net.controller().value(TRACK);
            return v == null || v.length() != 3 ? null : String.format(Locale.ROOT,
                    "along %.3f m, across %.3f m, heading %.3f rad", v.element(0), v.element(1), v.element(2));
        } catch (RuntimeException notLoaded) {
            return null; // no Course module loaded: nothing sensed to show
        }
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
