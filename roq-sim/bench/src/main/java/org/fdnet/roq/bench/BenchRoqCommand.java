package org.fdnet.roq.bench;

import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.bridge.SimBridge;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.CourseFormatException;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.JointCommand;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.roq.sim.SimOptions;
import org.fdnet.roq.testkit.CourseSpec;
import org.fdnet.roq.testkit.SimulatedRoq;
import org.fdnet.runtime.engine.DrivenClock;
import org.fdnet.runtime.cli.ParameterAssignment;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fdnet bench roq}, in two parts.
 * <ol type="a">
 *   <li>Stepped speed of a RoQ network driving the simulator through the {@link SimBridge} (one network advance
 *   per 1 ms tick) beside the plant alone stepped the same way (a snapshot read and a command each tick, no
 *   network), in the same run, alternating second by second so the machine's load falls on both alike. Before that, a
 *   robot test as a user writes it ({@link SimulatedRoq}: {@code --network} on {@code --test-course} with sensor
 *   noise, {@code --test-seconds} of simulated time, started, run, measured and closed) as a multiple of real time,
 *   beside the plant alone stepped through the same simulated time on the same course with the same options.</li>
 *   <li>{@link ReflexLatencyBench Reflex latency} in real time from stimuli (pushes), snapshot to applied command,
 *   for the tilt reflex and for the periodic path, the network recording with a logger, beside a bare Java echo of
 *   each snapshot's tick into the command slot.</li>
 * </ol>
 * {@code --part push}: {@link PushSurvivalBench}; {@code --part heading}: {@link HeadingDriftBench};
 * {@code --part breakthroughs}: {@link BreakthroughSweep}.
 */
@Command(name = "roq", mixinStandardHelpOptions = true,
        description = "(a) stepped speed of a RoQ network + simulator beside the simulator alone, and a robot test on"
                + " the test kit (SimulatedRoq) as a multiple of real time beside the plant alone; (b) real-time reflex"
                + " latency from pushes, stimulus snapshot to applied command, tilt reflex and periodic path, beside a"
                + " bare Java echo (same run); push: largest survivable push with the full network beside Balance and"
                + " Reflex unloaded; heading: drift off the course line with and without module Course; breakthroughs:"
                + " fragile cells broken under a loaded foot over many noise seeds, beside module Probing unloaded.")
public final class BenchRoqCommand implements Callable<Integer> {
    @Option(names = "--seconds", defaultValue = "60",
            description = "(a) simulated seconds for each measurement (default 60)")
    int seconds;

    @Option(names = "--test-course", defaultValue = "rubble:12",
            description = "(a) the robot test's course: a built-in name, rubble:SEED, slope:DEGREES or a .course file"
                    + " (default rubble:12)")
    String testCourse;

    @Option(names = "--test-seconds", defaultValue = "40",
            description = "(a) the robot test's simulated seconds (default 40; target: at least 10× real time)")
    int testSeconds;

    @Option(names = "--pushes", defaultValue = "100",
            description = "(b) pushes answered, reflex loaded and again unloaded (default 100; at most 4 wall s each)")
    int pushes;

    @Option(names = "--echo-seconds", defaultValue = "30",
            description = "(b) wall seconds of the bare Java echo baseline (default 30: ~30,000 snapshots)")
    int echoSeconds;

    @Option(names = "--part", defaultValue = "ab",
            description = "a, b or ab (default ab); push: largest survivable push with and without Balance and Reflex;"
                    + " heading: drift off the course line with and without module Course; breakthroughs: cells broken"
                    + " under a loaded foot over --noise seeds, with and without module Probing")
    String part;

    @Option(names = "--directions", split = ",", defaultValue = "0,45,90,135,180,225,270,315",
            description = "(push) push directions, degrees from +x (default every 45°)")
    double[] directions;

    @Option(names = "--offsets", split = ",", defaultValue = "0,0.35",
            description = "(push) push start, s after a leg lifts (default 0,0.35; the swing lasts 0.7 s)")
    double[] offsets;

    @Option(names = "--drops", defaultValue = "100",
            description = "(b) sole-force drops, one short run each (default 100, about 1.2 s each)")
    int drops;

    @Option(names = "--no-logger", description = "(b) without recording (default: record with a logger started here)")
    boolean noLogger;

    @Option(names = "--trace", description = "(b) one line per answer: when each stage ran after the stimulus's snapshot,"
            + " on which thread, and the garbage collections in between")
    boolean trace;

    @Option(names = "--seeds", split = ",", defaultValue = "12,2004,13",
            description = "(heading) rubble seeds (default 12,2004,13)")
    long[] seeds;

    @Option(names = "--heading-seconds", defaultValue = "70",
            description = "(heading) simulated seconds per run (default 70, ~3 m of rubble)")
    int headingSeconds;

    @Option(names = "--noise",
            description = "(breakthroughs, heading, push) sensor-noise seeds: a range FROM-TO or a list (default:"
                    + " breakthroughs 1-24; heading " + HEADING_NOISE + ", RoqCoursesTest's; push 7, one table a seed)")
    String noise;

    @Option(names = "--whole-scan",
            description = "(push) go on scanning every 50 N push up to the largest after the first failure, and print"
                    + " how many each variant survived (about twice the runs)")
    boolean wholeScan;

    @Option(names = "--param", paramLabel = "MODULE/NODE:NAME=VALUE",
            description = "(breakthroughs, heading) set a node parameter of --network before the runs (repeatable;"
                    + " the parameter must be in the file), as fdnet run --param does")
    List<String> params = new ArrayList<>();

    @Option(names = "--unload", split = ",", paramLabel = "MODULE",
            description = "(breakthroughs) modules of --network to unload for the runs, e.g. Balance (the baseline"
                    + " unloads Probing as well)")
    List<String> unload = new ArrayList<>();

    /** The robot test's sensor-noise seed (the kit's default). */
    static final long TEST_NOISE = 1;

    /** The heading runs' default noise seeds: RoqCoursesTest's eight. */
    static final String HEADING_NOISE = "5,105,205,305,405,505,605,705";

    @Option(names = "--sweep-seconds", defaultValue = "100",
            description = "(breakthroughs) simulated seconds per run (default 100, the demo's)")
    int sweepSeconds;

    @Option(names = "--course", defaultValue = "crossing", description = "course (default crossing, the demo's)")
    String course;

    @Option(names = "--network", defaultValue = "networks/roq-rubble.fdn", description = "(a, heading) network (default networks/roq-rubble.fdn, the demo's)")
    Path network;

    @Option(names = "--baseline-network", description = "(breakthroughs) the baseline: this network as it is, beside"
            + " --network on the same seeds (default: --network with module Probing unloaded)")
    Path baselineNetwork;

    @Option(names = "--reflex-network", defaultValue = "networks/roq-reflex-bench.fdn",
            description = "(b, push) network with a TiltReflex (default networks/roq-reflex-bench.fdn)")
    Path reflexNetwork;

    @Option(names = "--reflex-course", defaultValue = "flat", description = "(b, push) course (default flat)")
    String reflexCourse;

    @Override
    public Integer call() throws Exception {
        if (seconds < 1) {
            System.err.println("fdnet bench roq: --seconds must be at least 1, was " + seconds);
            return 2;
        }
        if (testSeconds < 1) {
            System.err.println("fdnet bench roq: --test-seconds must be at least 1, was " + testSeconds);
            return 2;
        }
        if (drops < 1) {
            System.err.println("fdnet bench roq: --drops must be at least 1, was " + drops);
            return 2;
        }
        if (pushes < 1) {
            System.err.println("fdnet bench roq: --pushes must be at least 1, was " + pushes);
            return 2;
        }
        if (echoSeconds < 1) {
            System.err.println("fdnet bench roq: --echo-seconds must be at least 1, was " + echoSeconds);
            return 2;
        }
        if (!part.matches("a|b|ab|push|heading|breakthroughs")) {
            System.err.println("fdnet bench roq: --part must be a, b, ab, push, heading or breakthroughs, was " + part);
            return 2;
        }
        String noiseText = noise != null ? noise : part.equals("heading") ? HEADING_NOISE
                : part.equals("push") ? "7" : "1-24";
        long[] noises = NoiseSeeds.parse(noiseText);
        if (noises.length == 0) {
            System.err.println("fdnet bench roq: --noise must be a range FROM-TO (FROM <= TO, at most 1000 seeds) or a"
                    + " comma-separated list of seeds, was " + noiseText);
            return 2;
        }
        if (sweepSeconds < 10) {
            System.err.println("fdnet bench roq: --sweep-seconds must be at least 10 (two crawl cycles), was "
                    + sweepSeconds);
            return 2;
        }
        for (double o : offsets) {
            if (!(o >= 0 && o < 0.7)) {
                System.err.println("fdnet bench roq: --offsets must lie in 0..0.7 s (within the 0.7 s swing), was " + o);
                return 2;
            }
        }
        for (double d : directions) {
            if (!Double.isFinite(d)) {
                System.err.println("fdnet bench roq: --directions must be finite degrees, was " + d);
                return 2;
            }
        }
        if (headingSeconds < 10) {
            System.err.println("fdnet bench roq: --heading-seconds must be at least 10 (two crawl cycles), was "
                    + headingSeconds);
            return 2;
        }
        if (!unload.isEmpty() && !part.equals("breakthroughs")) {
            System.err.println("fdnet bench roq: --unload applies to --part breakthroughs only, was given with --part "
                    + part);
            return 2;
        }
        try {
            if (part.equals("push")) {
                NetworkInfo definition = load(reflexNetwork);
                Course pushed = CourseLoader.resolve(reflexCourse);
                for (long seed : noises) {
                    new PushSurvivalBench(definition, pushed, seed, directions, offsets, 5, wholeScan).run();
                }
                return 0;
            }
            if (part.equals("breakthroughs") || part.equals("heading")) {
                NetworkInfo definition = withParams(load(network));
                if (definition == null) {
                    return 2;
                }
                for (String module : unload) {
                    if (module.equals("main") || definition.module(module) == null) {
                        System.err.println("fdnet bench roq: --unload " + module + ": " + definition.name()
                                + " has no such module to unload");
                        return 2;
                    }
                }
                if (part.equals("heading")) {
                    new HeadingDriftBench(definition, seeds, headingSeconds, noises).run();
                } else {
                    NetworkInfo beside = baselineNetwork == null ? null : load(baselineNetwork);
                    new BreakthroughSweep(definition, beside, CourseLoader.resolve(course), noises, sweepSeconds,
                            unload.toArray(String[]::new)).run();
                }
                return 0;
            }
            if (part.contains("a")) {
                Course tested = CourseSpec.parse(testCourse);
                robotTest(tested);
                stepped(CourseLoader.resolve(course), load(network));
            }
            if (part.contains("b")) {
                return new ReflexLatencyBench(CourseLoader.resolve(reflexCourse), load(reflexNetwork), reflexNetwork,
                        echoSeconds, pushes, drops, !noLogger, trace).run();
            }
            return 0;
        } catch (CourseFormatException | NetworkFileException e) {
            System.err.println("fdnet bench roq: " + e.getMessage());
            return 2;
        } catch (NoSuchFileException e) {
            System.err.println("fdnet bench roq: no network file " + e.getFile());
            return 2;
        } catch (IllegalArgumentException e) {
            System.err.println("fdnet bench roq: " + e.getMessage());
            return 2;
        }
    }

    /** {@code definition} with every {@code --param} applied, or null (said why) when one does not fit it. */
    private NetworkInfo withParams(NetworkInfo definition) {
        for (String p : params) {
            try {
                ParameterAssignment.parse(p).applyTo(definition);
            } catch (IllegalArgumentException e) {
                System.err.println("fdnet bench roq: --param " + p + ": " + e.getMessage());
                return null;
            }
        }
        if (!params.isEmpty()) {
            System.out.println("fdnet bench roq: " + definition.name() + " with " + String.join(", ", params));
        }
        return definition;
    }

    private static NetworkInfo load(Path file) throws NetworkFileException, NoSuchFileException {
        if (!Files.isRegularFile(file)) {
            throw new NoSuchFileException(file.toAbsolutePath().toString());
        }
        return NetworkRepository.load(file);
    }

    private void stepped(Course c, NetworkInfo definition) throws Exception {
        System.out.printf(Locale.ROOT, "fdnet bench roq: %s on course %s, %d simulated s of each, 1 ms ticks, alternating%n",
                network, c.name(), seconds);
        long netNanos = 0;
        long plantNanos = 0;
        long firings;
        try (RoqSimulator alone = RoqSimulator.open(c, SimMode.STEPPED);
             RoqSimulator driven = RoqSimulator.open(c, SimMode.STEPPED);
             RuntimeNetwork net = RuntimeNetwork.start(definition,
                     RuntimeOptions.defaults().drivenClock(new DrivenClock(0)))) {
            SimBridge bridge = SimBridge.stepped(net, driven, 0, 1);
            SensorSnapshot s = new SensorSnapshot();
            JointCommand command = new JointCommand();
            bridge.run(1000); // warm-up
            plantAlone(alone, s, command);
            for (int second = 1; second <= seconds; second++) {
                long t0 = System.nanoTime();
                bridge.run(1000);
                netNanos += System.nanoTime() - t0;
                plantNanos += plantAlone(alone, s, command);
                if (second % 10 == 0 || second == seconds) {
                    System.out.printf(Locale.ROOT, "  %3d s: network + plant %.1f µs per tick, plant alone %.1f µs per tick%n",
                            second, netNanos / 1e3 / (second * 1000.0), plantNanos / 1e3 / (second * 1000.0));
                }
            }
            firings = net.firings();
        }
        double withNet = seconds / (netNanos / 1e9);
        double plant = seconds / (plantNanos / 1e9);
        System.out.printf(Locale.ROOT, "baseline: plant alone              %6.1f sim s per wall s (%.1f µs per tick)%n",
                plant, plantNanos / 1e3 / (seconds * 1000.0));
        System.out.printf(Locale.ROOT, "network + plant (stepped bridge)   %6.1f sim s per wall s (%.1f µs per tick, %,d firings)%n",
                withNet, netNanos / 1e3 / (seconds * 1000.0), firings);
        double ratio = withNet / plant;
        System.out.printf(Locale.ROOT, "network + plant: %.2f× the plant alone (target ≥ 0.8: %s)%n",
                ratio, ratio >= 0.8 ? "met" : "NOT met");
    }

    /**
     * A robot test as a user's runs: {@code --network} on {@code --test-course}, noise seed {@value #TEST_NOISE}, for
     * {@code --test-seconds}, from start to close, timed whole, twice: as a suite's first test (the JVM loads and
     * compiles the classes on the way) and as a later one (the same test again: the target's figure); beside the
     * plant alone, opened, stepped through as many ticks on the same course with the kit's simulator options and
     * closed, in the same run. It runs before the stepped-bridge measurement, so the JVM has seen only the kit's path.
     */
    private void robotTest(Course c) {
        System.out.printf(Locale.ROOT, "robot test on the kit: %s on %s, noise %d, %d simulated s (SimulatedRoq: start,"
                + " run, measure, close), twice%n", network, testCourse, TEST_NOISE, testSeconds);
        long t = System.nanoTime();
        runTest(c, testSeconds);
        long firstNanos = System.nanoTime() - t;
        long t0 = System.nanoTime();
        String measured = runTest(c, testSeconds);
        long testNanos = System.nanoTime() - t0;
        long t1 = System.nanoTime();
        try (RoqSimulator alone = RoqSimulator.open(c, SimOptions.of(SimMode.STEPPED).withNoise(TEST_NOISE)
                .withRangeSensors(false))) {
            SensorSnapshot s = new SensorSnapshot();
            JointCommand command = new JointCommand();
            for (int second = 0; second < testSeconds; second++) {
                plantAlone(alone, s, command);
            }
        }
        long plantNanos = System.nanoTime() - t1;
        double test = testSeconds / (testNanos / 1e9);
        double plant = testSeconds / (plantNanos / 1e9);
        System.out.println("  " + measured);
        System.out.printf(Locale.ROOT, "baseline: plant alone, same course   %6.1f× real time (%.2f wall s)%n", plant,
                plantNanos / 1e9);
        System.out.printf(Locale.ROOT, "robot test, first in this JVM        %6.1f× real time (%.2f wall s; classes"
                + " loaded and compiled on the way)%n", testSeconds / (firstNanos / 1e9), firstNanos / 1e9);
        System.out.printf(Locale.ROOT, "robot test (SimulatedRoq)            %6.1f× real time (%.2f wall s, the same test"
                + " again; target ≥ 10×: %s)%n", test, testNanos / 1e9, test >= 10 ? "met" : "NOT met");
    }

    /** One robot test: {@code --network} on {@code c} for {@code seconds}, started, run and closed; its measures. */
    private String runTest(Course c, int seconds) {
        try (SimulatedRoq roq = SimulatedRoq.builder().network(network).course(c).noise(TEST_NOISE).start()) {
            roq.runFor(Duration.ofSeconds(seconds));
            return roq.measures().toString();
        }
    }

    /** 1000 ticks as the bridge steps them, without a network: step, read, send. Returns nanoseconds. */
    private static long plantAlone(RoqSimulator sim, SensorSnapshot s, JointCommand command) {
        long t0 = System.nanoTime();
        for (int k = 0; k < 1000; k++) {
            sim.step(1);
            sim.read(s);
            command.basedOnTick(s.tick());
            sim.send(command);
        }
        return System.nanoTime() - t0;
    }
}
