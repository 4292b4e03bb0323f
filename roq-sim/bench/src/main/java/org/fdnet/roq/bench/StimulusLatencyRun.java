package org.fdnet.roq.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.roq.bridge.SimBridge;
import org.fdnet.roq.node.JointTargets;
import org.fdnet.roq.node.RoqSensor;
import org.fdnet.roq.node.TiltReflex;
import org.fdnet.roq.sim.CellBreak;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.FragileCell;
import org.fdnet.roq.sim.Push;
import org.fdnet.roq.sim.RealTimeThreads;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;

/**
 * One real-time run of {@code bench roq} (b): pushes a walking RoQ, one push towards the corner of the leg in the
 * air at a time, and measures for each the ticks from the snapshot that first showed the stimulus — the first
 * attitude or gyro reading, after the push began, beyond the tilt reflex's own thresholds ({@code tilt},
 * {@code rate} of its {@link TiltReflex}) — to the tick the loop applied the first command computed from that
 * snapshot or a later one (its source tick, {@link org.fdnet.runtime.Value#tick()}), + 1: the tick it first shows
 * in a snapshot. The bridge sends only commands that changed, so every command counted changed the targets. A push
 * (not a drop: each drop has a run of its own) is armed only once every reading has stayed within those thresholds
 * for {@link #CALM_TICKS} ticks and the reflex's correction is back to zero (waiting at most 5 s): while RoQ still
 * moves beyond them no snapshot can show the next push, and while the reflex still braces for the last one, with the
 * same leg and aim, the next one's snapshot has nothing new for it to answer (session 8: 6 of 100 answers took 4–10
 * ms that way once the deeper crouch made the braces last longer).
 *
 * <pre>
 *  push ─▶ snapshot S: reading beyond threshold ─▶ network ─▶ JointTargets (source tick ≥ S) ─▶ applied at tick A
 *  latency = A + 1 − S   (the loop's applied-command ring gives A and the source tick of every command)
 * </pre>
 */
final class StimulusLatencyRun {
    /** A push that tips the crawl past the reflex's thresholds without felling it (TiltReflexTest). */
    static final double PUSH_NEWTONS = 300;
    static final double PUSH_SECONDS = 0.1;
    private static final double[] CORNER_DEGREES = {45, -45, 135, 225}; // fl, fr, hl, hr
    private static final int FRONT_LEFT = 0;
    private static final int HIND_RIGHT = 3;
    /** Wall time allowed a push, start to settled: the run ends there even if some pushes went unanswered. */
    private static final int SECONDS_A_PUSH = 4;
    /** After an answer, before the next push: the reflex holds 0.3 s and fades over 0.3 s more. */
    private static final long SETTLE_MILLIS = 1000;
    /**
     * Ticks every reading must have stayed within the reflex's thresholds before a push is armed: a push into a body
     * still moving beyond them shows in no snapshot (the first one after it is already beyond).
     */
    private static final long CALM_TICKS = 100;
    /** The longest a push waits for calm before it is armed regardless, ns. */
    private static final long MOST_CALM_WAIT_NANOS = 5_000_000_000L;

    record Outcome(int stimuli, int shown, LatencySample latencies, boolean fell, List<String> traces) {
    }

    /** Which stimulus a run applies. */
    enum Kind {
        /** Pushes on the body during leg swings, one run of the given length. */
        PUSH,
        /**
         * Sole-force drops: short runs on {@link #cellsUnderTheFeet} (as many as the run's {@code drops}), each breaking the cell under the front-left
         * foot while the hind-right leg (its diagonal partner) is in the air.
         */
        CELL_BREAK
    }

    private final Course course;
    private final NetworkInfo definition;
    private final boolean reflexLoaded;
    private final int pushes;
    private final int drops;
    private final LoggerClient client;
    private final boolean trace;
    private final AnswerStages stages = new AnswerStages();
    private final double tilt;
    private final double rate;
    private final String reflexModule;
    private final AtomicLong armedAfter = new AtomicLong(Long.MAX_VALUE);
    private final AtomicLong shownAt = new AtomicLong(-1);
    /** The tick of the newest reading beyond the reflex's thresholds, armed or not. */
    private final AtomicLong lastBeyond = new AtomicLong(Long.MIN_VALUE / 2);
    private final long[] appliedTicks = new long[64];
    private final long[] sourceTicks = new long[64];
    private long seen;

    StimulusLatencyRun(Course course, NetworkInfo definition, boolean reflexLoaded, int pushes, int drops,
                       LoggerClient client, boolean trace) {
        this.course = course;
        this.trace = trace;
        this.definition = definition;
        this.reflexLoaded = reflexLoaded;
        this.pushes = pushes;
        this.drops = drops;
        this.client = client;
        NodeRef reflex = SimBridge.nodesOf(definition, TiltReflex.class).stream().findFirst().orElseThrow(() ->
                new IllegalArgumentException("network " + definition.name() + " has no " + TiltReflex.class.getName()
                        + " (bench roq (b) measures it; networks/roq-reflex-bench.fdn has one)"));
        NodeInfo node = definition.node(reflex);
        tilt = parameter(node, "tilt", 0.15);
        rate = parameter(node, "rate", 1.0);
        reflexModule = reflex.module();
    }

    Outcome run(Kind kind) throws Exception {
        if (kind == Kind.PUSH) {
            return run(course, Kind.PUSH, pushes * SECONDS_A_PUSH);
        }
        Outcome sum = new Outcome(0, 0, new LatencySample(), false, new ArrayList<>());
        Course cells = cellsUnderTheFeet(course);
        for (int i = 0; i < drops; i++) {
            Outcome o = run(cells, Kind.CELL_BREAK, 4);
            o.latencies().addAllTo(sum.latencies());
            sum.traces().addAll(o.traces());
            sum = new Outcome(sum.stimuli() + o.stimuli(), sum.shown() + o.shown(), sum.latencies(), sum.fell() || o.fell(),
                    sum.traces());
        }
        return sum;
    }

    /** {@code c} with a strong fragile cell (1000 N, 8 cm deep: a drop that tips RoQ) under each standing foot, front-left's first. */
    static Course cellsUnderTheFeet(Course c) {
        List<FragileCell> cells = new ArrayList<>();
        double[] foot = new double[3];
        for (int leg = 0; leg < RoqGeometry.LEGS; leg++) {
            RoqGeometry.footInBody(leg, RoqGeometry.STANDING_POSE[0], RoqGeometry.STANDING_POSE[1],
                    RoqGeometry.STANDING_POSE[2], foot);
            cells.add(new FragileCell(c.startX() + foot[0], c.startY() + foot[1], 0.12, 0.12, 0.08, 1000));
        }
        return c.withFragileCells(cells);
    }

    private Outcome run(Course on, Kind kind, int runSeconds) throws Exception {
        RuntimeOptions options = RuntimeOptions.defaults().workerStart(RealTimeThreads::promoteCurrentThread);
        if (client != null) {
            // Every event goes to the logger, but closing this run's network does not wait for the logger to commit
            // them (a flush took ~1.9 s of each 3 s drop run): the bench closes the client at the end and reports
            // how many of the accepted events the logger committed.
            options = options.sink(trace ? this::timedAccept : client::accept);
        }
        LatencySample sample = new LatencySample();
        List<String> traces = new ArrayList<>();
        int stimuli = 0;
        int shown = 0;
        boolean fell = false;
        try (RoqSimulator sim = RoqSimulator.open(on, SimMode.REAL_TIME);
             RuntimeNetwork net = RuntimeNetwork.start(definition, options);
             SimBridge bridge = SimBridge.realTime(net, sim)) {
            if (!reflexLoaded && !net.controller().unload(reflexModule).executed()) {
                throw new IllegalStateException("cannot unload module " + reflexModule);
            }
            List<AutoCloseable> watches = new ArrayList<>();
            for (NodeRef ref : sensors(net, "attitude")) {
                watches.add(net.controller().observe(ref, (r, id, v) -> check(v, tilt)));
            }
            for (NodeRef ref : sensors(net, "imu_gyro")) {
                watches.add(net.controller().observe(ref, (r, id, v) -> check(v, rate)));
            }
            NodeRef reflexPress = dataNamed(net, "reflex press");
            if (trace) {
                if (reflexPress != null) {
                    watches.add(net.controller().observe(reflexPress, (r, id, v) -> stages.reflexWrote(v)));
                }
                for (NodeRef ref : net.readDefinition(def -> SimBridge.nodesOf(def, JointTargets.class))) {
                    watches.add(net.controller().observe(ref, (r, id, v) -> stages.targetsWritten(v.tick())));
                }
            }
            NodeRef phase = dataNamed(net, "gait phase");
            NodeRef fallen = dataNamed(net, "fallen");
            SensorSnapshot s = new SensorSnapshot();
            long end = System.nanoTime() + runSeconds * 1_000_000_000L;
            if (kind == Kind.PUSH) {
                Thread.sleep(1500); // stand up and start walking
            }
            seen = sim.appliedCommands(0, appliedTicks, sourceTicks);
            BridgeAllocation allocation = trace && kind == Kind.PUSH ? BridgeAllocation.start(bridge) : null;
            long calmDeadline = System.nanoTime() + MOST_CALM_WAIT_NANOS;
            while (System.nanoTime() < end && sample.count() < pushes && !(fell = isTrue(net, fallen))) {
                int leg = legInTheAir(net, phase, end);
                if (leg < 0 || (kind == Kind.CELL_BREAK && leg != HIND_RIGHT)) {
                    continue;
                }
                long now = sim.read(s);
                if (kind == Kind.PUSH && (now - lastBeyond.get() < CALM_TICKS || braced(net, reflexPress))
                        && System.nanoTime() < calmDeadline) {
                    continue; // still answering the last push: a snapshot now could not show the next one
                }
                calmDeadline = System.nanoTime() + MOST_CALM_WAIT_NANOS;
                long first = now + 3;
                shownAt.set(-1);
                stages.arm();
                armedAfter.set(first);
                sim.stimulate(kind == Kind.PUSH
                        ? new Push(first * 0.001, PUSH_SECONDS, PUSH_NEWTONS, CORNER_DEGREES[leg])
                        : new CellBreak(first * 0.001, FRONT_LEFT));
                stimuli++;
                long latency = await(sim);
                armedAfter.set(Long.MAX_VALUE);
                if (shownAt.get() >= 0) {
                    shown++;
                }
                if (latency >= 0) {
                    sample.add(latency);
                    if (trace) {
                        traces.add(stages.describe(latency, shownAt.get() + latency - 1));
                    }
                }
                if (kind == Kind.CELL_BREAK) {
                    break; // one break a run: the cell is gone
                }
                Thread.sleep(SETTLE_MILLIS); // let the walk settle before the next push
            }
            if (allocation != null) {
                traces.add(allocation.describe());
            }
            for (AutoCloseable w : watches) {
                w.close();
            }
        }
        return new Outcome(stimuli, shown, sample, fell, traces);
    }

    private void timedAccept(NetworkEvent event) {
        long start = System.nanoTime();
        client.accept(event);
        stages.sinkTook(System.nanoTime() - start);
    }

    /** A reading beyond {@code limit} (in roll or pitch, the first two elements) after the armed push began. */
    private void check(Value v, double limit) {
        stages.sensorCommitted(v.tick());
        boolean beyond = v.length() >= 2 && (Math.abs(v.element(0)) > limit || Math.abs(v.element(1)) > limit);
        if (beyond) {
            lastBeyond.accumulateAndGet(v.tick(), Math::max);
        }
        if (beyond && v.tick() > armedAfter.get() && shownAt.get() < 0 && shownAt.compareAndSet(-1, v.tick())) {
            stages.shown(v.tick());
        }
    }

    /** Waits for the stimulus to show and for the first command computed from it; its latency, or −1. */
    private long await(RoqSimulator sim) throws InterruptedException {
        long deadline = System.nanoTime() + 900_000_000L;
        while (System.nanoTime() < deadline) {
            long count = sim.appliedCommands(seen, appliedTicks, sourceTicks);
            long firstCopied = Math.max(seen, count - appliedTicks.length);
            long shown = shownAt.get();
            for (long n = firstCopied; n < count && shown >= 0; n++) {
                int i = (int) (n - firstCopied);
                if (sourceTicks[i] >= shown) {
                    seen = n + 1;
                    return appliedTicks[i] + 1 - shown;
                }
            }
            seen = count;
            Thread.sleep(0, 200_000);
        }
        return -1;
    }

    private static int legInTheAir(RuntimeNetwork net, NodeRef phase, long end) throws InterruptedException {
        while (System.nanoTime() < end) {
            Value p = phase == null ? null : net.controller().value(phase);
            if (p != null && p.length() >= 2 && p.element(1) > 0.5) {
                Thread.sleep(100); // well into the swing, the foot up
                return (int) p.element(0);
            }
            Thread.sleep(2);
        }
        return -1;
    }

    /** Whether the reflex's correction ({@code press}, null or unloaded: none) is not all zero: it still braces. */
    private static boolean braced(RuntimeNetwork net, NodeRef press) {
        Value v;
        try {
            v = press == null ? null : net.controller().value(press);
        } catch (RuntimeException unloaded) {
            return false;
        }
        if (v == null) {
            return false;
        }
        for (int i = 0; i < v.length(); i++) {
            if (v.element(i) != 0) {
                return true;
            }
        }
        return false;
    }

    private static boolean isTrue(RuntimeNetwork net, NodeRef ref) {
        Value v = ref == null ? null : net.controller().value(ref);
        return v != null && v.asBoolean();
    }

    private static List<NodeRef> sensors(RuntimeNetwork net, String channel) {
        return net.readDefinition(def -> {
            List<NodeRef> refs = new ArrayList<>();
            for (NodeRef ref : SimBridge.nodesOf(def, RoqSensor.class)) {
                if (channel.equals(def.node(ref).parameter("channel"))) {
                    refs.add(ref);
                }
            }
            return refs;
        });
    }

    private static NodeRef dataNamed(RuntimeNetwork net, String name) {
        return net.readDefinition(def -> {
            for (ModuleInfo m : def.modules()) {
                for (NodeInfo n : m.nodes()) {
                    if (n.name().equals(name)) {
                        return new NodeRef(m.name(), n.name());
                    }
                }
            }
            return null;
        });
    }

    private static double parameter(NodeInfo node, String name, double fallback) {
        String text = node.parameter(name);
        return text == null ? fallback : Double.parseDouble(text.strip());
    }

    /** "reflex loaded" / "reflex unloaded" with the thresholds. */
    String describe() {
        return String.format(Locale.ROOT, "module %s %s (thresholds tilt %.2f rad, rate %.2f rad/s)", reflexModule,
                reflexLoaded ? "loaded" : "unloaded", tilt, rate);
    }
}
