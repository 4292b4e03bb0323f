package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.*;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * A crawl gait, the static walk: one leg in the air at a time, in the order hind-right, front-right, hind-left,
 * front-left. Each leg owns a quarter of the {@code cycle} (s, default 5): the body first has time to shift
 * (see {@link KeepBalance}), then the leg swings {@code stride} m (default 0.15) forward, {@code clearance} m
 * (default 0.06) high, while the feet on the ground move backwards under the body at a steady speed. Writes, in
 * Writer order, (0) the feet's centres in the body frame (12 numbers) for a body {@code height} m high (default
 * 0.27) and (1) the gait phase {leg whose quarter it is, 1 while that leg is in the air else 0}. Needs a
 * {@code period}. Its phase only moves while it fires: held, it stops the walk where it is; resumed, it goes on.
 *
 * <p>Probing (when a Reader connects the verdict of {@link ProbeGround} and it is there, i.e. module Probing is
 * loaded): at each touchdown the gait stops with the swung foot {@code clearance}/2 above its foothold and writes
 * a third phase number, a new probe attempt; it waits until the verdict answers that attempt. Accepted, it steps
 * on. Rejected, it chooses a shorter step ({@code retreat} m, default 0.08, further back) and probes again, at
 * most {@code tries} times (default 3); the last foothold is stepped on whatever the verdict, and reported. If the
 * verdict disappears (Probing unloaded), it steps on without probing.
 *
 * <p>{@code swing} (default 0.14) is the part of the cycle each leg is in the air, so each foot is down 1 − swing of
 * it (the duty factor, 0.86 by default); {@code shift} (default 0.08) is the part of each quarter before its leg
 * lifts. swing + shift ≤ 0.25 keeps one leg in the air at a time; 0.25 and 0 give the fastest crawl, duty factor
 * 3/4, with a leg in the air all the time.
 *
 * <p>{@code settle} (s, default 0): RoQ stands that long from the gait's first firing before its first step, so
 * that {@link HoldCourse} can learn the gyro's bias while the body is still: its phase names no leg (−1) then, so
 * the balance does not shift the body; in the first half of it the feet move smoothly from the standing pose the
 * simulator sets RoQ down in to the gait's. With a settle the crawl starts a quarter of a cycle on, front-right
 * lifting first: there the feet's stagger along the body is the same on the left as on the right, so moving the
 * planted feet into it does not turn the body (from phase 0 the left feet stand ahead of the right ones, and the
 * body turned 0.17 rad and went on creeping round at 10 mrad/s while it stood, measured).
 *
 * <p>{@code rise} (default 0): lift-off by contact. The part of each swing in which the foot only rises; it goes
 * forward after that, once its sole (the input named {@code foot forces}, when connected) is unloaded. Should the
 * foot still bear load half-way through its swing (a brace, the body sagging onto it), the phase waits for it, at
 * most 1 s. A foot that started forward while still down was driven along the ground into whatever stood before it
 * (on {@code crossing}, a crust's rear face: 14 of 35 loaded-foot breakthroughs over 24 noise seeds, measured).
 *
 * <p>{@code stance} (m, default the standing pose's 0.43): how far each foot stands from the body's centre line.
 * The simulator sets RoQ down in its standing pose; each leg moves to the stance while it swings, so after the
 * first four steps the feet walk at the stance's width.
 */
public class CrawlGait extends Relation {
    /** hr, fr, hl, fl. */
    static final int[] ORDER = {3, 1, 2, 0};
    /** The part of the cycle at the start of each quarter before its leg lifts (time for the body to shift). */
    private double shift;
    /** The most the body turns per stance, rad, whatever {@code steer} says. */
    static final double MAX_TURN = 0.3;
    /** The most the turn changes per firing, rad per stance. */
    private static final double TURN_RATE = 0.002;
    /** The turn the feet follow now, rad per stance (positive: to the left). */
    private double turnPerStance;
    /** Each foot's turn about the body's centre now, rad. */
    private final double[] rotation = new double[LEGS];
    /** Each foot's turn when its swing began, rad. */
    private final double[] liftRotation = new double[LEGS];
    /** Whether each leg was swinging at the last firing. */
    private final boolean[] swung = new boolean[LEGS];
    /** The part of the cycle each leg is in the air: the duty factor is 1 − swing. */
    private double swing;

    private final double[] feet = new double[3 * LEGS];
    private final double[] home = new double[3 * LEGS];
    /** Each foot's distance from the body's centre line now (it moves to {@code stance} while the leg swings). */
    private final double[] side = new double[LEGS];
    private double stance;
    private double cycle;
    private double stride;
    private double clearance;
    private double height;
    private double phase;
    private double lastSeconds = Double.NaN;
    /** The network time of the first firing, s. */
    private double firstSeconds = Double.NaN;
    /** How long RoQ stands before the first step, s (time for a gyro to learn its bias, see {@link HoldCourse}). */
    private double settle;
    private double maxStep;
    private double retreat;
    private int tries;
    private final double[] shorten = new double[LEGS];
    private int probingLeg = -1;
    private int rejections;
    private long attempt;
    private long unprobedSteps;
    /** The part of each swing in which the foot only rises, before it moves forward (0: it moves from the start). */
    private double rise;
    /** Whether each swinging foot has left the ground (its sole unloaded after the rise) and may move forward. */
    private final boolean[] cleared = new boolean[LEGS];
    /** How far along its way forward each swinging foot is (0..1), and at which part of its swing that was. */
    private final double[] progress = new double[LEGS];
    private final double[] progressAt = new double[LEGS];
    /** Each sole's force, a running mean over {@link #SOLE_SMOOTHING}, N (NaN before the first reading). */
    private final double[] sole = {Double.NaN, Double.NaN, Double.NaN, Double.NaN};
    /** Time constant of the soles' running mean, s. */
    private static final double SOLE_SMOOTHING = 0.03;
    /** How long the phase has waited for the swinging foot to clear the ground, s. */
    private double liftWait;
    /** Swings that had not cleared the ground after {@link #MOST_LIFT_WAIT} and moved on regardless. */
    private long stuckLifts;
    /** A sole reading less than this carries nothing: its foot is off the ground, N. */
    static final double UNLOADED = 10;
    /** The longest the phase waits for a swinging foot to clear the ground, s. */
    static final double MOST_LIFT_WAIT = 1.0;

    public static final ParameterSpec<Double> CYCLE = ParameterSpec.number("cycle").unit("s").atLeast(0.5).defaultValue(5.0)
            .describe("the time of one cycle, each leg owning a quarter of it");
    public static final ParameterSpec<Double> STRIDE = ParameterSpec.number("stride").unit("m").range(0, 0.3)
            .defaultValue(0.15).describe("how far each swing moves the leg forward");
    public static final ParameterSpec<Double> CLEARANCE = ParameterSpec.number("clearance").unit("m").range(0, 0.15)
            .defaultValue(0.06).describe("how high the swinging foot goes");
    public static final ParameterSpec<Double> HEIGHT = ParameterSpec.number("height").unit("m").range(0.15, 0.4)
            .defaultValue(0.27).describe("the body's height the feet are placed for");
    public static final ParameterSpec<Double> SWING = ParameterSpec.number("swing").unit("cycle").range(0.05, 0.25)
            .defaultValue(0.14).describe("the part of the cycle each leg is in the air (one leg at a time)");
    public static final ParameterSpec<Double> SHIFT = ParameterSpec.number("shift").unit("cycle").range(0, 0.2)
            .defaultValue(0.08).describe("the part of each quarter before its leg lifts (swing + shift at most 0.25)");
    public static final ParameterSpec<Double> RETREAT = ParameterSpec.number("retreat").unit("m").atLeast(0)
            .defaultValue(0.08).describe("how much shorter the next step is after a foothold gave way (at most stride + 0.1)");
    public static final ParameterSpec<Long> TRIES = ParameterSpec.whole("tries").range(1, 10).defaultValue(3L)
            .describe("footholds probed at most per touchdown");
    public static final ParameterSpec<Double> RISE = ParameterSpec.number("rise").unit("swing").range(0, 0.45)
            .defaultValue(0.0).describe("the part of each swing in which the foot only rises (lift-off by contact)");
    public static final ParameterSpec<Double> SETTLE = ParameterSpec.number("settle").unit("s").range(0, 30)
            .defaultValue(0.0).describe("how long RoQ stands from the first firing before its first step");
    public static final ParameterSpec<Double> STANCE = ParameterSpec.number("stance").unit("m")
            .range(HIP_POSITION[0][1], 0.5).defaultDescribed("the standing pose's")
            .describe("how far each foot stands from the body's centre line");

    @Override
    protected void init(NodeParameters p) {
        cycle = CYCLE.read(p);
        stride = STRIDE.read(p);
        clearance = CLEARANCE.read(p);
        height = HEIGHT.read(p);
        swing = SWING.read(p);
        shift = SHIFT.read(p);
        if (shift + swing > 0.25 + 1e-9) {
            throw p.conflict(SHIFT, SWING, "swing + shift must be at most 0.25 of the cycle (one leg in the air at a time)");
        }
        retreat = RETREAT.read(p);
        if (retreat > stride + 0.1) {
            throw p.conflict(RETREAT, STRIDE, "retreat must be at most stride + 0.1 m");
        }
        tries = TRIES.read(p).intValue();
        rise = RISE.read(p);
        settle = SETTLE.read(p);
        phase = settle > 0 ? 0.25 : 0;
        maxStep = 4 * PERIOD.readOr(p, 10L) / 1000.0;
        double[] foot = new double[3];
        for (int leg = 0; leg < LEGS; leg++) {
            footInBody(leg, STANDING_POSE[0], STANDING_POSE[1], STANDING_POSE[2], foot);
            home[3 * leg] = foot[0];
            home[3 * leg + 1] = foot[1];
            home[3 * leg + 2] = -(height - FOOT_RADIUS);
            side[leg] = Math.abs(foot[1]);
        }
        stance = STANCE.readOr(p, side[0]);
    }

    @Override
    protected void compute(RelationContext c) {
        double now = c.seconds();
        int verdictIn = c.inputIndex("probe verdict");
        boolean probes = verdictIn >= 0 && c.input(verdictIn) != null;
        if (probingLeg >= 0) {
            awaitVerdict(c, probes ? c.input(verdictIn) : null);
        }
        steer(c);
        double advanced = 0;
        if (Double.isNaN(firstSeconds)) {
            firstSeconds = now;
        }
        Value soles = rise > 0 ? SensedFeet.named(c, "foot forces") : null;
        double elapsed = Double.isNaN(lastSeconds) ? 0 : Math.max(0, now - lastSeconds);
        double firing = elapsed;
        if (!Double.isNaN(lastSeconds) && probingLeg < 0 && now - firstSeconds >= settle && waitsForLiftoff(c, elapsed)) {
            elapsed = 0; // the swinging foot still bears load: hold the phase while it rises
        }
        if (!Double.isNaN(lastSeconds) && probingLeg < 0 && now - firstSeconds >= settle && elapsed > 0) {
            // a held gait does not fire: its phase waits; after a resume it goes on from there
            double before = phase;
            phase += Math.min(maxStep, elapsed) / cycle;
            phase -= Math.floor(phase);
            stopAtTouchdown(before, probes);
            advanced = phase - before + (phase < before ? 1 : 0);
        }
        lastSeconds = now;
        int quarter = Math.min(3, (int) (phase * 4));
        boolean inAir = false;
        for (int q = 0; q < 4; q++) {
            int leg = ORDER[q];
            double u = phase - q * 0.25 - shift;
            u -= Math.floor(u);
            double x;
            double lift = 0;
            double y = Math.signum(home[3 * leg + 1]) * side[leg];
            double turn;
            if (leg == probingLeg) {
                x = stride / 2 - shorten[leg];
                lift = clearance / 2;
                inAir = true;
                turn = rotation[leg];
            } else if (u < swing) {
                double s = u / swing;
                if (!swung[leg]) {
                    swung[leg] = true;
                    liftRotation[leg] = rotation[leg];
                }
                rotation[leg] = liftRotation[leg] + (turnPerStance / 2 - liftRotation[leg]) * s;
                turn = rotation[leg];
                if (side[leg] != stance) {
                    double from = side[leg];
                    y = Math.signum(home[3 * leg + 1]) * (from + (stance - from) * s);
                    if (s > 0.95) {
                        side[leg] = stance;
                    }
                }
                double from = -stride / 2 - shorten[leg];
                x = from + (stride / 2 - from) * forward(leg, s, soles, firing);
                lift = clearance * Math.sin(Math.PI * s);
                if (probes && s > 0.5) {
                    lift = clearance / 2 + lift / 2; // lands clearance/2 above the foothold, where probing starts
                }
                inAir |= q == quarter;
            } else {
                double s = (u - swing) / (1 - swing);
                x = stride / 2 - shorten[leg] - stride * s;
                swung[leg] = false;
                cleared[leg] = false;
                sole[leg] = Double.NaN; // its next swing's running mean starts from the load it lifts off with
                rotation[leg] -= turnPerStance * advanced / (1 - swing);
                turn = rotation[leg];
            }
            // turning: the feet on the ground all turn by the same -turnPerStance per stance about the body's
            // centre, so the body turns by +turnPerStance on the ground; a swing sets its foot down turned by half
            // of it the other way
            double fx = home[3 * leg] + x;
            feet[3 * leg] = fx * Math.cos(turn) - y * Math.sin(turn);
            feet[3 * leg + 1] = fx * Math.sin(turn) + y * Math.cos(turn);
            feet[3 * leg + 2] = home[3 * leg + 2] + lift;
        }
        if (now - firstSeconds < settle / 2) {
            fromStandingPose((now - firstSeconds) / (settle / 2));
        }
        c.output(0, Value.ofDoubles(feet));
        if (c.outputCount() > 1) {
            // while RoQ settles no leg is about to lift (-1): the balance leaves the body where it stands, until the
            // last second of it
            int next = now - firstSeconds < settle - preShift() ? -1 : ORDER[quarter];
            c.output(1, verdictIn >= 0
                    ? Value.ofDoubles(next, inAir ? 1 : 0, probingLeg >= 0 ? attempt : 0)
                    : Value.ofDoubles(next, inAir ? 1 : 0));
        }
    }

    /**
     * How far along its way forward a swinging foot is, 0..1, at {@code s} of its swing. Without a {@code rise} it
     * moves forward from the start of the swing. With one, it first only rises — a foot that starts forward while
     * still on the ground drags along it and, against a block's or a crust's face, pushes into it — and moves
     * forward once it has risen for {@code rise} of the swing and its sole (input {@code foot forces}, when read; a
     * 30 ms running mean, the contact chatters) carries less than {@link #UNLOADED} N. It then covers the way in
     * what is left of the swing. (Stopping it while its sole bore load again later in the swing, a foot meeting a
     * block's face, left it behind the block: rubble seed 21 stalled and turned, measured.)
     */
    private double forward(int leg, double s, Value soles, double dt) {
        if (rise <= 0) {
            return s;
        }
        boolean read = soles != null && soles.length() > leg;
        if (read) {
            double raw = soles.element(leg);
            sole[leg] = Double.isNaN(sole[leg]) ? raw
                    : sole[leg] + (raw - sole[leg]) * (1 - Math.exp(-dt / SOLE_SMOOTHING));
        }
        boolean free = !read || sole[leg] < UNLOADED;
        if (!cleared[leg]) {
            if (s >= rise && free) {
                cleared[leg] = true;
                progress[leg] = 0;
                progressAt[leg] = s;
            }
            return 0;
        }
        if (s > progressAt[leg]) {
            progress[leg] += (1 - progress[leg]) * Math.min(1, (s - progressAt[leg]) / (1 - progressAt[leg]));
        }
        progressAt[leg] = s;
        return progress[leg];
    }

    /**
     * Whether the phase waits, this firing, for the swinging foot to leave the ground: it has been in the air for
     * half its swing and its sole still bears load (a brace, a body sagging onto it). The wait lasts at most
     * {@link #MOST_LIFT_WAIT}; then the swing goes on and it is reported.
     */
    private boolean waitsForLiftoff(RelationContext c, double elapsed) {
        if (rise <= 0) {
            return false;
        }
        int q = Math.min(3, (int) (phase * 4));
        int leg = ORDER[q];
        double u = phase - q * 0.25 - shift;
        if (u < 0.5 * swing || u >= swing || cleared[leg]) {
            liftWait = 0;
            return false;
        }
        liftWait += elapsed;
        if (liftWait <= MOST_LIFT_WAIT) {
            return true;
        }
        cleared[leg] = true;
        progress[leg] = 0;
        progressAt[leg] = u / swing;
        stuckLifts++;
        c.report("leg " + leg + " still bore load " + MOST_LIFT_WAIT + " s into its swing; swung on (" + stuckLifts
                + " so far)");
        liftWait = 0;
        return false;
    }

    /**
     * The first half of {@code settle}: the feet move smoothly from where the simulator set them down (the standing
     * pose) to the gait's, {@code f} of the way, so the start does not jolt the body.
     */
    private void fromStandingPose(double f) {
        double w = f * f * (3 - 2 * f);
        double standZ = -(standingHeight() - FOOT_RADIUS);
        for (int leg = 0; leg < LEGS; leg++) {
            feet[3 * leg] = home[3 * leg] + (feet[3 * leg] - home[3 * leg]) * w;
            feet[3 * leg + 1] = home[3 * leg + 1] + (feet[3 * leg + 1] - home[3 * leg + 1]) * w;
            feet[3 * leg + 2] = standZ + (feet[3 * leg + 2] - standZ) * w;
        }
    }

    /**
     * The end of {@code settle} in which the phase already names the first leg to lift, so the balance has the body
     * over the other three before it lifts: a second, or half the settling if that is shorter.
     */
    private double preShift() {
        return Math.min(1, settle / 2);
    }

    /** With probing, a swing that reached its touchdown in this period stops there and a probe attempt starts. */
    private void stopAtTouchdown(double before, boolean probes) {
        int q = Math.min(3, (int) (before * 4));
        double touchdown = q * 0.25 + shift + swing;
        double travelled = phase - before + (phase < before ? 1 : 0);
        double toTouchdown = touchdown - before;
        if (toTouchdown <= 0 || toTouchdown > travelled) {
            return;
        }
        int leg = ORDER[q];
        shorten[leg] = 0;
        if (!probes) {
            return;
        }
        phase = touchdown - Math.floor(touchdown);
        probingLeg = leg;
        rejections = 0;
        attempt++;
    }

    /**
     * Follows the Data named {@code steer} (rad per stance, e.g. from {@link HoldCourse}) when it is connected and
     * there, else goes straight; the turn changes by at most {@link #TURN_RATE} per firing so the feet do not jump.
     */
    private void steer(RelationContext c) {
        Value wished = c.inputIndex("steer") >= 0 ? c.input("steer") : null;
        double target = wished == null || wished.length() < 1 ? 0 : wished.element(0);
        target = Math.max(-MAX_TURN, Math.min(MAX_TURN, target));
        turnPerStance += Math.max(-TURN_RATE, Math.min(TURN_RATE, target - turnPerStance));
    }

    private void awaitVerdict(RelationContext c, Value v) {
        if (v == null) {
            probingLeg = -1; // Probing unloaded: step on
            unprobedSteps++;
            return;
        }
        if (v.length() < 3 || (long) v.element(2) != attempt || (int) v.element(0) != probingLeg) {
            return;
        }
        if (v.element(1) > 0) {
            probingLeg = -1;
            return;
        }
        rejections++;
        if (rejections >= tries) {
            unprobedSteps++;
            c.report("leg " + probingLeg + ": " + rejections + " footholds rejected, stepping on the last ("
                    + unprobedSteps + " so far)");
            probingLeg = -1;
            return;
        }
        shorten[probingLeg] += retreat;
        attempt++;
        c.report("leg " + probingLeg + ": foothold rejected, a step " + shorten[probingLeg] + " m shorter");
    }
}
