package org.fdnet.roq.testkit;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.function.Consumer;
import java.util.function.Predicate;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.bridge.BreakthroughCauses;
import org.fdnet.roq.bridge.CourseMeter;
import org.fdnet.roq.bridge.SimBridge;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.Push;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.roq.sim.SimOptions;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.loading.ClassLoadingPolicy;
import org.fdnet.testkit.TestNetwork;

/**
 * The simulated RoQ under a network, stepped on one thread: the MuJoCo plant advances 1 ms per tick and the network
 * runs on a driven clock in lockstep with it, so the same test gives the same robot, bit for bit
 * ({@link #stateHash()}) and the same network events ({@link #eventLogHash()}), however loaded the machine is, and
 * runs as fast as the CPU allows. Sensor noise is on, from a seed, unless the builder turns it off.
 *
 * <p>A <em>step</em> is 10 ms of simulated time: hooks run before and after each, and the ground-truth measures
 * ({@link #measures()}) are sampled after each. Every event the network emits is kept, so a failing test can be
 * recorded for {@code fdnet viewer --replay} ({@link RoqExtension} does that).
 *
 * <pre>{@code
 * try (SimulatedRoq roq = SimulatedRoq.builder().network(Path.of("networks/lab-rubble.fdn"))
 *         .course("rubble:12").noise(7).start()) {
 *     roq.runFor(Duration.ofSeconds(40));
 *     roq.assertThat().noFall().walkedAtLeast(0.8).noLoadedFootBreakthrough();
 * }
 * }</pre>
 */
public final class SimulatedRoq implements AutoCloseable {
    /** Simulated time of one step. */
    public static final Duration STEP = Duration.ofMillis(10);
    /** Without a {@code fallen} Data in the network, a tilt above this (rad) at any sample counts as a fall. */
    public static final double FALLEN_TILT = Math.PI / 3;

    private static final int STEP_TICKS = 10;
    /** Ticks run when the robot starts, before time 0 of the test: the first snapshot the measures start from. */
    private static final int FIRST_TICKS = 1;

    private final String name;
    private final Course course;
    private final RoqSimulator simulator;
    private final TestNetwork network;
    private final SimBridge bridge;
    private final CourseMeter meter;
    private final double startX;
    private final NodeRef fallenData;
    private final NodeRef marginData;
    private final List<Consumer<SimulatedRoq>> beforeStep = new ArrayList<>();
    private final List<Consumer<SimulatedRoq>> afterStep = new ArrayList<>();
    private final List<double[]> trail = new ArrayList<>();
    private SensorSnapshot last;
    private long ticks;
    private double tilt;
    private boolean tippedOver;
    private double smallestMargin = Double.NaN;
    private long marginSeenAt;

    private SimulatedRoq(String name, Course course, RoqSimulator simulator, TestNetwork network) {
        this.name = name;
        this.course = course;
        this.simulator = simulator;
        this.network = network;
        this.bridge = SimBridge.stepped(network.engine(), simulator, network.startMicros(), 1);
        bridge.run(FIRST_TICKS);
        ticks = FIRST_TICKS;
        last = bridge.lastSnapshot();
        startX = last.groundTruthBodyPosition(0);
        meter = new CourseMeter(last, course.fragileCells());
        fallenData = network.engine().readDefinition(d -> dataNamed(d, "fallen"));
        marginData = network.engine().readDefinition(d -> dataNamed(d, "margin"));
        marginSeenAt = initialTime(marginData);
        trail.add(new double[] {startX, last.groundTruthBodyPosition(1)});
    }

    /** @return a builder: name the network, then the course and the noise seed */
    public static Builder builder() {
        return new Builder();
    }

    /**
     * Runs {@code duration} of simulated time in {@link #STEP}s (the last one shorter when it does not divide).
     *
     * @param duration how long, ≥ 0
     */
    public void advance(Duration duration) {
        long remaining = duration.toMillis();
        if (remaining < 0) {
            throw new IllegalArgumentException("advance by a negative duration: " + duration);
        }
        while (remaining > 0) {
            int step = (int) Math.min(STEP_TICKS, remaining);
            step(step);
            remaining -= step;
        }
    }

    /** The same as {@link #advance}: runs {@code duration} of simulated time. */
    public void runFor(Duration duration) {
        advance(duration);
    }

    /**
     * Steps until {@code condition} holds, at most until {@code deadline} of simulated time from now.
     *
     * @param description what is awaited, for the failure message
     * @param condition   tested before the first step and after each
     * @param deadline    simulated time to run at most
     * @throws AssertionError naming the description, the simulated time and the measures when the deadline passes
     */
    public void runUntil(String description, Predicate<SimulatedRoq> condition, Duration deadline) {
        long end = ticks + deadline.toMillis();
        while (!condition.test(this)) {
            if (ticks >= end) {
                throw new AssertionError(String.format(Locale.ROOT, "%s: %s did not happen within %.2f s of"
                        + " simulated time\n  %s", name, description, deadline.toMillis() / 1e3, measures()));
            }
            step((int) Math.min(STEP_TICKS, end - ticks));
        }
    }

    /** Runs {@code hook} before every step from now on (e.g. to set a Data or push at a given time). */
    public void beforeEachStep(Consumer<SimulatedRoq> hook) {
        beforeStep.add(Objects.requireNonNull(hook, "hook"));
    }

    /** Runs {@code hook} after every step from now on, once the measures are sampled. */
    public void afterEachStep(Consumer<SimulatedRoq> hook) {
        afterStep.add(Objects.requireNonNull(hook, "hook"));
    }

    /**
     * Pushes the body: the simulator applies {@code push} at its start time (the plant's simulated seconds, which
     * run {@value #FIRST_TICKS} ms ahead of {@link #time()}).
     *
     * @param push force, direction, start and duration; a start before now is refused
     */
    public void push(Push push) {
        if (push.startSeconds() * 1000 < ticks) {
            throw new IllegalArgumentException(String.format(Locale.ROOT, "a push starting at %.3f s lies before the"
                    + " simulated time %.3f s", push.startSeconds(), ticks / 1e3));
        }
        simulator.stimulate(push);
    }

    /** Loads a module of the network. @throws AssertionError when the network refuses, with its reason */
    public void load(String module) {
        network.load(module);
    }

    /** Unloads a module of the network. @throws AssertionError when the network refuses, with its reason */
    public void unload(String module) {
        network.unload(module);
    }

    /** @return the network, to set, send, read and assert values */
    public TestNetwork network() {
        return network;
    }

    /** @return the last sensor snapshot (ground truth included); valid until the next step */
    public SensorSnapshot snapshot() {
        return last;
    }

    /** @return simulated time since the run started */
    public Duration time() {
        return Duration.ofMillis(ticks - FIRST_TICKS);
    }

    /** @return the course the robot walks */
    public Course course() {
        return course;
    }

    /** @return what failure messages call this run: network, course and noise seed */
    public String name() {
        return name;
    }

    /** @return everything measured so far */
    public RoqMeasures measures() {
        BreakthroughCauses causes = meter.causes();
        return new RoqMeasures((ticks - FIRST_TICKS) / 1e3, last.groundTruthBodyPosition(0) - startX, meter.maxTrackError(),
                meter.maxHeadingError(), tilt, fallen(), meter.probeBroken(), meter.loadedBreakthroughs(),
                causes.swinging(), causes.standing(), causes.slid(), smallestMargin);
    }

    /** @return assertions on the measures as they are now */
    public RoqAssertions assertThat() {
        return new RoqAssertions(name, measures());
    }

    /**
     * @return a hash of the whole physical state (time, positions, velocities, accelerations, fragile cells), as hex:
     *         the same test run twice gives the same hash
     */
    public String stateHash() {
        return HexFormat.of().toHexDigits(simulator.stateHash());
    }

    /**
     * @return a hash of every event the network emitted so far (values, relation states, commands, node names), each
     *         with its time counted from the start of the run, as hex: the same test run twice gives the same hash
     *         although the driven clock starts at each run's wall-clock time
     */
    public String eventLogHash() {
        MessageDigest sha = sha256();
        long start = network.startMicros();
        for (NetworkEvent e : network.events()) {
            sha.update(relativeToStart(e, start).toString().getBytes(StandardCharsets.UTF_8));
        }
        return HexFormat.of().formatHex(sha.digest());
    }

    private static NetworkEvent relativeToStart(NetworkEvent e, long start) {
        long t = e.time() - start;
        if (e instanceof DataValueEvent d) {
            return new DataValueEvent(d.sourceId(), t, d.value());
        }
        if (e instanceof RelationValueEvent r) {
            return new RelationValueEvent(r.sourceId(), t, r.value());
        }
        if (e instanceof NetworkCommandEvent c) {
            return new NetworkCommandEvent(c.sourceId(), t, c.sourceType(), c.command(), c.paramsId(), c.paramsType());
        }
        NodeNamedEvent n = (NodeNamedEvent) e;
        return new NodeNamedEvent(n.sourceId(), t, n.kind(), n.name());
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java runtime has SHA-256", e);
        }
    }

    /** @return the body's (x, y) every 5 mm it moved, for pictures */
    List<double[]> trail() {
        return trail;
    }

    RoqSimulator simulator() {
        return simulator;
    }

    @Override
    public void close() {
        try {
            bridge.close();
            network.close();
        } finally {
            simulator.close();
        }
    }

    private void step(int stepTicks) {
        for (Consumer<SimulatedRoq> hook : beforeStep) {
            hook.accept(this);
        }
        bridge.run(stepTicks);
        ticks += stepTicks;
        last = bridge.lastSnapshot();
        meter.sample(last, network.engine());
        tilt = Math.max(tilt, Math.max(Math.abs(last.roll()), Math.abs(last.pitch())));
        tippedOver |= tilt > FALLEN_TILT;
        sampleMargin();
        double[] end = trail.get(trail.size() - 1);
        double x = last.groundTruthBodyPosition(0);
        double y = last.groundTruthBodyPosition(1);
        if (Math.hypot(x - end[0], y - end[1]) >= 0.005) {
            trail.add(new double[] {x, y});
        }
        for (Consumer<SimulatedRoq> hook : afterStep) {
            hook.accept(this);
        }
    }

    private void sampleMargin() {
        if (marginData == null) {
            return;
        }
        Value v = network.controller().value(marginData);
        if (v != null && v.time() > marginSeenAt && v.isScalar()) {
            smallestMargin = Double.isNaN(smallestMargin) ? v.asDouble() : Math.min(smallestMargin, v.asDouble());
        }
    }

    private long initialTime(NodeRef data) {
        if (data == null) {
            return Long.MAX_VALUE;
        }
        Value v = network.controller().value(data);
        return v == null ? Long.MIN_VALUE : v.time();
    }

    private boolean fallen() {
        if (fallenData != null) {
            Value v = network.controller().value(fallenData);
            if (v != null) {
                return v.asBoolean() || tippedOver;
            }
        }
        return tippedOver;
    }

    private static NodeRef dataNamed(NetworkInfo definition, String name) {
        for (ModuleInfo m : definition.modules()) {
            for (NodeInfo n : m.nodes()) {
                if (n.kind() == NodeKind.DATA && n.name().equals(name)) {
                    return new NodeRef(m.name(), n.name());
                }
            }
        }
        return null;
    }

    /** Names the network, the course and the noise seed of a {@link SimulatedRoq}, then starts it. */
    public static final class Builder {
        private NetworkInfo definition;
        private ClassLoadingPolicy policy;
        private String networkName;
        private Course course;
        private String courseName;
        private long noise = 1;
        private boolean sensorNoise = true;
        private final List<String> unloaded = new ArrayList<>();

        private Builder() {
        }

        /**
         * @param fdn the network file; its node classes load as {@link TestNetwork#start(Path)} loads them
         * @return this
         * @throws IllegalArgumentException naming the file and every problem when it does not load
         */
        public Builder network(Path fdn) {
            try {
                definition = NetworkRepository.load(fdn);
            } catch (NetworkFileException e) {
                throw new IllegalArgumentException(fdn + " does not load: " + e.getMessage(), e);
            }
            policy = ClassLoadingPolicy.forNetworkFile(fdn, List.of(Path.of("").toAbsolutePath()));
            networkName = fdn.getFileName().toString();
            return this;
        }

        /**
         * @param network a network built in code (built-in node classes only)
         * @return this
         */
        public Builder network(NetworkInfo network) {
            definition = Objects.requireNonNull(network, "network");
            policy = ClassLoadingPolicy.builtInOnly();
            networkName = network.name();
            return this;
        }

        /**
         * @param spec a built-in course name, {@code rubble:SEED}, {@code slope:DEGREES} or a {@code .course} path
         *             ({@link CourseSpec})
         * @return this
         */
        public Builder course(String spec) {
            course = CourseSpec.parse(spec);
            courseName = spec;
            return this;
        }

        /**
         * @param file a {@code .course} file
         * @return this
         */
        public Builder course(Path file) {
            return course(file.toString());
        }

        /**
         * @param c a course made in code
         * @return this
         */
        public Builder course(Course c) {
            course = Objects.requireNonNull(c, "course");
            courseName = c.name();
            return this;
        }

        /**
         * @param seed the sensor-noise seed (noise is on unless {@link #withoutNoise()} turns it off; the seed makes
         *             it repeatable)
         * @return this
         */
        public Builder noise(long seed) {
            noise = seed;
            return this;
        }

        /**
         * Turns sensor noise off: every sensor reads the plant exactly (for tests of a mechanism rather than of its
         * robustness). The noise seed is then ignored.
         *
         * @return this
         */
        public Builder withoutNoise() {
            sensorNoise = false;
            return this;
        }

        /**
         * @param modules modules to unload before the run starts
         * @return this
         */
        public Builder unload(String... modules) {
            unloaded.addAll(List.of(modules));
            return this;
        }

        /**
         * Opens the simulator, starts the network on a driven clock beside it and runs the first tick.
         *
         * @return the running robot; close it (or let {@link RoqExtension} do it)
         * @throws IllegalStateException when no network was named
         * @throws IllegalArgumentException when the network does not start or a module cannot be unloaded
         */
        public SimulatedRoq start() {
            if (definition == null) {
                throw new IllegalStateException("name a network first: builder().network(Path) or network(NetworkInfo)");
            }
            Course c = course != null ? course : CourseSpec.parse("flat");
            String label = String.format(Locale.ROOT, "%s on %s, %s%s", networkName,
                    courseName != null ? courseName : "flat", sensorNoise ? "noise " + noise : "noise off",
                    unloaded.isEmpty() ? "" : ", without " + String.join(", ", unloaded));
            RoqSimulator sim = RoqSimulator.open(c, simOptions());
            TestNetwork net = null;
            try {
                net = TestNetwork.start(definition, policy, label, System.currentTimeMillis() * 1000);
                for (String module : unloaded) {
                    net.unload(module);
                }
                return new SimulatedRoq(label, c, sim, net);
            } catch (AssertionError refused) {
                closeAll(net, sim);
                throw new IllegalArgumentException(refused.getMessage(), refused);
            } catch (RuntimeException e) {
                closeAll(net, sim);
                throw e;
            }
        }

        /** Stepped; no range sensors (no RoQ node reads them, and they cost a ray cast per sensor each tick). */
        private SimOptions simOptions() {
            SimOptions stepped = SimOptions.of(SimMode.STEPPED).withRangeSensors(false);
            return sensorNoise ? stepped.withNoise(noise) : stepped;
        }

        private static void closeAll(TestNetwork net, RoqSimulator sim) {
            try {
                if (net != null) {
                    net.close();
                }
            } finally {
                sim.close();
            }
        }
    }
}
