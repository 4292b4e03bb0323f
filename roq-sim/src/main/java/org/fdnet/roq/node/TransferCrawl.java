package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.FOOT_RADIUS;
import static org.fdnet.roq.sim.RoqGeometry.LEGS;
import static org.fdnet.roq.sim.RoqGeometry.STANDING_POSE;
import static org.fdnet.roq.sim.RoqGeometry.footInBody;
import static org.fdnet.roq.sim.RoqGeometry.standingHeight;

import java.util.Locale;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * The weight-transfer crawl: one leg in the air at a time (hind-right, front-right, hind-left, front-left), the body
 * moving only while all four feet are down, and no leg lifted before the weight is off it and on the foot set down
 * last. Each step of leg L, the foot N set down before it being still unproved:
 *
 * <ol>
 *   <li><b>shift</b> — N's share of the weight is moved onto it through the force distribution over {@code
 *   transfer} s ({@link DistributeForces}, tracked by {@link TrackSoleForces}) while the body moves, with limited
 *   acceleration, until the measured centre of pressure lies inside the triangle of the three feet other than L by
 *   {@code margin} m, at the point where N carries {@code proofShare} of the weight (the other two the rest, evenly)
 *   — the body's progress comes from the footholds moving ahead;</li>
 *   <li><b>unload</b> — L's share of the weight is moved, over {@code transfer} s, onto the other three: N now
 *   carries what it will carry while L swings. This is N's probe ({@link FootholdProof}): held {@code hold} s it is
 *   accepted; a foothold that gives way (its force collapses) is rejected while L still stands — the body goes back
 *   over the triangle without N, N is lifted and set down {@code retreat} m shorter, and is proved again. The
 *   unloading waits while it would ask another standing foot for more than that foot bore when it was proved;</li>
 *   <li><b>swing</b> — L rises until its sole is free, moves to its foothold {@code stride}·5/8 ahead of the feet's
 *   centre and comes down until its sole finds the ground ({@link SwingPath}); it is the next step's N.</li>
 * </ol>
 *
 * <p>With {@code planReach} the steps are planned against each leg's reach and load ({@link LegReach}): the legs
 * go in turn around the body (hind-right, front-right, front-left, hind-left), so that N and L are on one side or at
 * one end and the weight that goes onto N is the weight that comes off L with the body near the feet's centre; the
 * shift goes to the place nearest where the body stands best over its feet ({@code lead} of the stride ahead of their
 * centre) at which the weight comes down inside the triangle by {@code margin} and with at least {@code leastLoad} on
 * each of its feet, N carries at least {@code proofShare}, every foot stays within its leg's reach, and no other foot
 * is planned to carry more than 0.9 of what it bore when proved or its leg can hold — in that precedence, the last
 * given up first when not all can hold ({@link PlanarConstraints}); and the foothold is beside the feet's centre,
 * half a stride ahead of its hip where the body stands, no farther than its reach less {@code reachMargin} of it.
 *
 * <p>Feet that stay where they were set: a foot is held where it found the ground (its sensed place against the
 * other feet's), not where it was sent, so the legs do not push against each other through the ground. Its sensed
 * place (joint angles, {@link SensedFeet}) against the body's motion (the mean of the feet's) tells if it slid more
 * than {@value #SLIP} m; slips are counted into the Data named {@code slips}, and with {@code replaceSlid} such a foot
 * is re-placed where it was set at the next step. Rejected footholds are counted into {@code footholds rejected}.
 *
 * <p>Inputs by name: {@code foot forces}, {@code joint angles}, {@code attitude}, {@code sole targets} (the
 * distribution's), {@code steer} (rad per cycle, optional, e.g. from {@link HoldCourse}). Outputs by name: {@code gait
 * feet} (12 numbers, the feet in the body frame, {@link Feet}) and {@code gait phase} ({@link GaitPhase}). It acts
 * every 10 ms. RoQ first stands {@code settle} s.
 */
public class TransferCrawl extends Relation {
    /** hr, fr, hl, fl. */
    static final int[] ORDER = {3, 1, 2, 0};
    /** hr, fr, fl, hl: around the body, the order of the planned crawl ({@code planReach}). */
    static final int[] AROUND_ORDER = {3, 1, 0, 2};
    /** How far a standing foot may slide before it is re-placed, m. */
    static final double SLIP = 0.02;
    /** How long a foot must stand that far off before it counts as slid (not a jolt of the body), s. */
    private static final double SLID_FOR = 0.2;
    /** The feet in order around the body: fl, fr, hr, hl. */
    private static final int[] AROUND = {0, 1, 3, 2};
    private static final double STEP = 0.0095;
    /** The most the heading target turns per cycle, rad. */
    private static final double MAX_TURN = 0.3;
    /** Speeds of the body: m/s across the ground, rad/s of turn; body height change, m/s. */
    private static final double BODY_SPEED = 0.3;
    private static final double BODY_ACCELERATION = 0.6;
    private static final double TURN_SPEED = 0.2;
    private static final double HEIGHT_SPEED = 0.02;
    /** How close the body must be to where the shift takes it, m. */
    private static final double THERE = 0.005;
    /** The longest a shift waits for the margin before the crawl goes on regardless, s. */
    private static final double MOST_SHIFT_WAIT = 3;
    /** The longest an unloading waits while it would ask a foot for more than it bore when proved, s. */
    private static final double MOST_OVERLOAD_WAIT = 1;
    /** The part of its proved load the shift plans a foot to carry at most, and the part it may be asked for. */
    private static final double PLANNED_OF_PROVEN = 0.9;
    private static final double ASKED_OF_PROVEN = 1.05;
    /** The longest a foot rises waiting for its sole to come free before the lift is given up, s. */
    private static final double MOST_RISE = 1.0;
    /** A sole under this carries nothing; a sole at this has found the ground, N. */
    private static final double FREE = 6;
    private static final double TOUCH = 20;
    /** A foot whose peak passed this and then collapsed gave way, N. */
    private static final double FIRM = 25;
    /** A foot just set down counts as loaded from this sole force on, N (DistributeForces' least, by default). */
    private static final double LOADED = 15;

    /**
     * Where the step is: standing before the first; a foot just set down (the next step begins at the next firing);
     * shifting; unloading; holding the proof; swinging; going back over the three feet after a foothold gave way;
     * re-placing that foot.
     */
    enum State { SETTLE, LOAD, SHIFT, UNLOAD, HOLD, SWING, RESTORE, RESWING }

    public static final ParameterSpec<Double> STRIDE = ParameterSpec.number("stride").unit("m").range(0, 0.4)
            .defaultValue(0.3).describe("how far each foot moves ahead in a cycle");
    public static final ParameterSpec<Double> CLEARANCE = ParameterSpec.number("clearance").unit("m").range(0, 0.15)
            .defaultValue(0.06).describe("how high a swinging foot goes above the ground");
    public static final ParameterSpec<Double> HEIGHT = ParameterSpec.number("height").unit("m").range(0.15, 0.4)
            .defaultValue(0.27).describe("the body's height the feet are placed for");
    public static final ParameterSpec<Double> STANCE = ParameterSpec.number("stance").unit("m").range(0.15, 0.5)
            .defaultValue(0.30).describe("how far each foot stands from the body's centre line");
    public static final ParameterSpec<Double> MARGIN = ParameterSpec.number("margin").unit("m").range(0, 0.15)
            .defaultValue(0.03).describe("how far inside the triangle of the three others the weight must be before a leg unloads");
    public static final ParameterSpec<Double> PROOF_SHARE = ParameterSpec.number("proofShare").unit("weight")
            .range(1.0 / 3, 0.5).defaultValue(0.4).describe("the share of the weight the foot being proved carries while the next leg swings (planned: at least)");
    public static final ParameterSpec<Boolean> PLAN_REACH = ParameterSpec.flag("planReach").defaultValue(false)
            .describe("whether shifts and footholds are planned within each leg's reach (else the weight point and"
                    + " footholds ahead of the feet's centre)");
    public static final ParameterSpec<Double> LEAST_LOAD = ParameterSpec.number("leastLoad").unit("N").range(0, 60)
            .defaultValue(25.0).describe("the least load the shift plans for every foot of the triangle a leg swings over");
    public static final ParameterSpec<Double> YAW_MARGIN = ParameterSpec.number("yawMargin").unit("rad").range(0, 0.6)
            .defaultValue(0.1).describe("how far inside its yaw range every hip is planned to stay");
    public static final ParameterSpec<Double> INWARD = ParameterSpec.number("inward").unit("m").range(0.06, 0.3)
            .defaultValue(0.1).describe("how far out from its hip every foot is planned to stay at least");
    public static final ParameterSpec<Double> REACH_MARGIN = ParameterSpec.number("reachMargin").unit("reach")
            .range(0, 0.9).defaultValue(0.1).describe("the part of a leg's reach ahead a new foothold keeps free");
    public static final ParameterSpec<Double> LEAD = ParameterSpec.number("lead").unit("stride").range(-0.5, 0.5)
            .defaultValue(0.125).describe("how far ahead of the feet's centre the body is planned to stand");
    public static final ParameterSpec<Double> TRANSFER = ParameterSpec.number("transfer").unit("s").range(0.05, 2)
            .defaultValue(0.4).describe("how long moving a leg's share of the weight takes");
    public static final ParameterSpec<Double> HOLD = ParameterSpec.number("hold").unit("s").range(0.11, 2)
            .defaultValue(0.2).describe("how long a new foothold must bear its load (above a fragile cell's 0.1 s)");
    public static final ParameterSpec<Double> SWING_SPEED = ParameterSpec.number("swingSpeed").unit("m/s")
            .range(0.05, 2).defaultValue(0.6).describe("how fast a swinging foot moves over the ground");
    public static final ParameterSpec<Double> DESCENT = ParameterSpec.number("descent").unit("m/s").range(0.02, 1)
            .defaultValue(0.15).describe("how fast a foot comes down near the ground it expects");
    public static final ParameterSpec<Double> DEPTH = ParameterSpec.number("depth").unit("m").range(0.01, 0.2)
            .defaultValue(0.1).describe("how far below the expected ground a foot looks for footing");
    public static final ParameterSpec<Double> RETREAT = ParameterSpec.number("retreat").unit("m").range(0, 0.3)
            .defaultValue(0.06).describe("how much shorter a foothold is set after one gave way");
    public static final ParameterSpec<Long> TRIES = ParameterSpec.whole("tries").range(1, 10).defaultValue(3L)
            .describe("footholds set back at most per step (then the same spot is proved again)");
    public static final ParameterSpec<Boolean> REPLACE_SLID = ParameterSpec.flag("replaceSlid").defaultValue(false)
            .describe("whether a foot that slid is re-placed where it was set (else only counted)");
    public static final ParameterSpec<Double> SETTLE = ParameterSpec.number("settle").unit("s").range(0, 30)
            .defaultValue(0.0).describe("how long RoQ stands before its first step");

    private double stride;
    private double clearance;
    private double height;
    private double stance;
    private double margin;
    private double proofShare;
    private LegReach reach;
    private double reachMargin;
    private double leastLoad;
    private boolean planReach;
    private double lead;
    private final PlanarConstraints plan = new PlanarConstraints(24);
    private final int[] tri = new int[3];
    private double transfer;
    private double retreat;
    private int tries;
    private double settle;
    private boolean replaceSlid;

    private final double[] homeX = new double[LEGS];
    private final double[] homeY = new double[LEGS];
    /** Each foot's place on the ground (the gait's ground frame), and its height in the body frame when set down. */
    private final double[] gx = new double[LEGS];
    private final double[] gy = new double[LEGS];
    private final double[] gz = new double[LEGS];
    private double bx;
    private double by;
    private double psi;
    private double psiTarget;
    private double lift;
    private final SensedFeet sensed = new SensedFeet();
    private final SoleContact soles = new SoleContact(FREE, TOUCH);
    private SwingPath path;
    private FootholdProof proof;
    private final double[] cop = new double[2];
    private double biasX;
    private double biasY;
    private boolean biasKnown;
    private final double[] px = new double[3];
    private final double[] py = new double[3];
    private final double[] slip0 = new double[LEGS];
    /** The load each foot bore when its foothold was proved, N (the start's footholds are taken as firm). */
    private final double[] proven = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
    /** The body's correction from the measured centre of pressure, m (ground frame). */
    private double corrX;
    /** The body's speed over the ground now, m/s. */
    private double speed;
    private double corrY;
    private final boolean[] slipped = new boolean[LEGS];
    /** How long each foot has stood more than {@link #SLIP} off its place, s. */
    private final double[] slidFor = new double[LEGS];
    private final Feet feet = new Feet();

    private State state = State.SETTLE;
    private double stateTime;
    private double first = Double.NaN;
    private double last = Double.NaN;
    /** Index into {@link #ORDER} of the leg to lift next. */
    private int next;
    /** The leg lifted this step (the next in order, or one being re-placed). */
    private int leg = -1;
    /** The foot set down last and not yet proved, or −1. */
    private int proving = -1;
    private long attempt;
    private int unloading = -1;
    private double share;
    private int rejectedHere;
    private boolean replacing;
    private long rejected;
    private long slips;
    /** Lifts given up because the rising foot never came free. */
    private long stuckLifts;

    @Override
    protected void init(NodeParameters p) {
        stride = STRIDE.read(p);
        clearance = CLEARANCE.read(p);
        height = HEIGHT.read(p);
        stance = STANCE.read(p);
        margin = MARGIN.read(p);
        proofShare = PROOF_SHARE.read(p);
        reach = new LegReach(YAW_MARGIN.read(p), INWARD.read(p));
        reachMargin = REACH_MARGIN.read(p);
        leastLoad = LEAST_LOAD.read(p);
        planReach = PLAN_REACH.read(p);
        lead = LEAD.read(p);
        transfer = TRANSFER.read(p);
        retreat = RETREAT.read(p);
        tries = TRIES.read(p).intValue();
        settle = SETTLE.read(p);
        replaceSlid = REPLACE_SLID.read(p);
        path = new SwingPath(0.3, SWING_SPEED.read(p), DESCENT.read(p), DEPTH.read(p));
        proof = new FootholdProof(HOLD.read(p), FIRM);
        double[] foot = new double[3];
        double standZ = -(standingHeight() - FOOT_RADIUS);
        for (int l = 0; l < LEGS; l++) {
            footInBody(l, STANDING_POSE[0], STANDING_POSE[1], STANDING_POSE[2], foot);
            homeX[l] = foot[0];
            homeY[l] = Math.signum(foot[1]) * stance;
            gx[l] = foot[0];
            gy[l] = foot[1];
            gz[l] = standZ;
        }
        lift = 0;
    }

    @Override
    protected void compute(RelationContext c) {
        double now = c.seconds();
        if (!Double.isNaN(last) && now - last < STEP) {
            return;
        }
        double dt = Double.isNaN(last) ? 0 : Math.min(0.05, now - last);
        last = now;
        if (Double.isNaN(first)) {
            first = now;
        }
        if (!soles.read(SensedFeet.named(c, "foot forces"), dt) || !sensed.read(SensedFeet.named(c, "joint angles"),
                SensedFeet.named(c, "foot forces"), SensedFeet.named(c, "attitude"))) {
            return;
        }
        learnBias(dt);
        stateTime += dt;
        step(c, now, dt);
        moveBody(dt);
        watchSlips(dt);
        write(c);
    }

    /** The state machine of one step; see the class comment. */
    private void step(RelationContext c, double now, double dt) {
        switch (state) {
            case SETTLE -> {
                if (now - first >= settle) {
                    beginStep(c);
                }
            }
            case LOAD -> {
                beginStep(c);
            }
            case SHIFT -> {
                if (unloading >= 0) {
                    // the foot set down last is loaded through the distribution while the body shifts
                    share = Math.max(0, share - dt / transfer);
                    // its loading ends when its sole bears the least load the distribution asks (the admittance
                    // follows the target with a lag), or after one more transfer time at most
                    if (share <= 0 && (soles.force(proving) >= LOADED || stateTime > 2 * transfer)) {
                        unloading = -1;
                        recordSetDown(proving);
                    }
                }
                if (proved(c, dt) && unloading < 0 && readyToUnload(leg)) {
                    to(State.UNLOAD);
                    unloading = leg;
                    share = 0;
                }
            }
            case UNLOAD, HOLD -> {
                if (!overloads(c) || stateTime > (planReach ? MOST_OVERLOAD_WAIT : MOST_SHIFT_WAIT)) {
                    share = Math.min(1, share + dt / transfer);
                }
                if (share >= 1 && state == State.UNLOAD) {
                    to(State.HOLD);
                }
                FootholdProof.Verdict v = proving < 0 ? FootholdProof.Verdict.ACCEPTED
                        : proof.observe(soles.force(proving), target(c, proving), state == State.HOLD, dt);
                if (v == FootholdProof.Verdict.REJECTED) {
                    reject(c);
                } else if (v == FootholdProof.Verdict.ACCEPTED && state == State.HOLD) {
                    if (proving >= 0) {
                        proven[proving] = soles.force(proving);
                    }
                    proving = -1;
                    unloading = -1;
                    share = 0;
                    startSwing(leg);
                    to(State.SWING);
                }
            }
            case SWING -> {
                SwingPath.Stage s = path.advance(dt, soles.liftedOff(leg), soles.touchedDown(leg));
                if (s == SwingPath.Stage.RISE && stateTime > MOST_RISE) {
                    // the body sags onto the rising leg: the weight is not off it after all; set it back down, shift
                    stuckLifts++;
                    c.report("leg " + leg + " still bore load " + MOST_RISE + " s into its rise; set back down ("
                            + stuckLifts + " so far)");
                    to(State.SHIFT);
                } else if (s == SwingPath.Stage.DOWN) {
                    setDown(leg);
                } else if (s == SwingPath.Stage.NO_FOOTING) {
                    noFooting(c, leg);
                }
            }
            case RESTORE -> {
                share = Math.min(1, share + dt / transfer);
                if (share >= 1 && readyToUnload(proving)) {
                    startReswing(proving);
                }
            }
            case RESWING -> {
                SwingPath.Stage s = path.advance(dt, soles.liftedOff(proving), soles.touchedDown(proving));
                if (s == SwingPath.Stage.DOWN) {
                    int l = proving;
                    setDown(l);
                } else if (s == SwingPath.Stage.NO_FOOTING) {
                    noFooting(c, proving);
                }
            }
        }
    }

    /**
     * Whether moving more weight off the leg being unloaded would ask a standing foot (other than the one being
     * proved) for more than it bore when it was proved: the unloading then waits (at most {@value #MOST_SHIFT_WAIT} s)
     * while the body settles where the shift took it.
     */
    private boolean overloads(RelationContext c) {
        Value t = SensedFeet.named(c, "sole targets");
        if (t == null || t.length() < LEGS) {
            return false;
        }
        for (int k = 0; k < LEGS; k++) {
            if (k != leg && k != proving && t.element(k) > (planReach ? ASKED_OF_PROVEN : 1) * proven[k]) {
                return true;
            }
        }
        return false;
    }

    /** Whether the foot being proved has not given way so far (a rejection starts the re-placing). */
    private boolean proved(RelationContext c, double dt) {
        if (proving < 0) {
            return true;
        }
        if (proof.observe(soles.force(proving), target(c, proving), false, dt) == FootholdProof.Verdict.REJECTED) {
            reject(c);
            return false;
        }
        return true;
    }

    /** Chooses the leg of the next step (a slipped foot first, else the next in order) and starts shifting. */
    private void beginStep(RelationContext c) {
        replacing = false;
        leg = planReach ? AROUND_ORDER[next] : ORDER[next];
        for (int l = 0; l < LEGS && replaceSlid; l++) {
            if (slipped[l] && l != proving) {
                leg = l;
                replacing = true;
                break;
            }
        }
        if (!replacing) {
            psiTarget += Math.max(-MAX_TURN, Math.min(MAX_TURN, steer(c))) / 4;
        }
        to(State.SHIFT);
    }

    /**
     * The foothold of the leg about to swing: where it was set, when re-placed; else ahead. Unplanned, {@code
     * stride}·5/8 ahead of the feet's centre; with {@code planReach}, beside the feet's centre as when standing and
     * half a stride ahead of its hip as the body stands now — no farther than its reach less {@code reachMargin} of
     * it, so that it stays within reach while the body moves on over it.
     */
    private void startSwing(int l) {
        double tx;
        double ty;
        if (replacing) {
            tx = gx[l];
            ty = gy[l];
            slipped[l] = false;
        } else {
            double[] centre = feetCentre();
            double ct = Math.cos(psiTarget);
            double st = Math.sin(psiTarget);
            double fx;
            double across;
            double fromX;
            double fromY;
            if (planReach) {
                // across: beside the feet's centre; along: from the hip where the body stands now
                double sideX = centre[0] - bx;
                double sideY = centre[1] - by;
                across = -st * sideX + ct * sideY + homeY[l];
                double ahead = Math.min(stride / 2, (1 - reachMargin) * reach.along(LegReach.outward(l, across)));
                fx = homeX[l] + ahead;
                fromX = bx;
                fromY = by;
            } else {
                across = homeY[l];
                fx = homeX[l] + stride * 5 / 8;
                fromX = centre[0];
                fromY = centre[1];
            }
            tx = fromX + ct * fx - st * across;
            ty = fromY + st * fx + ct * across;
        }
        double[] here = footGround(l);
        path.start(here[0], here[1], gz[l], tx, ty, expectedGround(l), planReach ? highestGround(l) : expectedGround(l),
                clearance);
    }

    /** The foot under re-placing goes back {@code retreat} m (unless it has been set back {@code tries} times). */
    private void startReswing(int l) {
        double back = rejectedHere <= tries ? retreat : 0;
        double[] here = footGround(l);
        path.start(here[0], here[1], gz[l], gx[l] - back * Math.cos(psi), gy[l] - back * Math.sin(psi),
                expectedGround(l), clearance / 2);
        to(State.RESWING);
    }

    /** The swinging foot found the ground: it is the one to prove now, loaded through the distribution. */
    private void setDown(int l) {
        // the foot stays where it found the ground (its sensed place, against the other feet's), not where it was
        // sent: holding it elsewhere would set the legs against each other through the ground
        double rx = 0;
        double ry = 0;
        int n = 0;
        for (int k = 0; k < LEGS; k++) {
            if (k != l) {
                double[] e = sensedGround(k);
                rx += e[0] - gx[k];
                ry += e[1] - gy[k];
                n++;
            }
        }
        double[] e = sensedGround(l);
        gx[l] = e[0] - rx / n;
        gy[l] = e[1] - ry / n;
        gz[l] = path.z();
        proving = l;
        attempt++;
        proof.start();
        unloading = l;
        share = 1;
        if (state == State.SWING) {
            rejectedHere = 0;
            if (!replacing) {
                next = (next + 1) % LEGS;
            }
        }
        to(State.LOAD);
    }

    /** The foothold gave way under the load: the body goes back over the other three, then the foot is re-placed. */
    private void reject(RelationContext c) {
        rejected++;
        rejectedHere++;
        c.report("leg " + proving + ": foothold gave way under " + Math.round(proof.peak()) + " N, re-placing ("
                + rejected + " so far)");
        if (c.outputIndex("footholds rejected") >= 0) {
            c.output("footholds rejected", Value.of(rejected));
        }
        unloading = proving;
        share = 0;
        to(State.RESTORE);
    }

    /** No ground within reach under the foot: it goes back by the retreat and tries again. */
    private void noFooting(RelationContext c, int l) {
        rejected++;
        rejectedHere++;
        c.report("leg " + l + ": no footing, setting the foot back");
        double[] here = footGround(l);
        path.start(here[0], here[1], path.z(), here[0] - retreat * Math.cos(psi), here[1] - retreat * Math.sin(psi),
                expectedGround(l), clearance / 2);
    }

    /** Whether the body is where the shift takes it and the weight lies inside the triangle without {@code l}. */
    private boolean readyToUnload(int l) {
        double[] t = shiftTarget(l);
        boolean there = Math.hypot(t[0] - bx, t[1] - by) < THERE && Math.abs(psiTarget - psi) < 0.01;
        if (!sensed.centreOfPressure(DistributeForces.WEIGHT / 2, cop)) {
            return false;
        }
        int n = 0;
        for (int k : AROUND) {
            if (k != l) {
                px[n] = sensed.position[3 * k];
                py[n] = sensed.position[3 * k + 1];
                n++;
            }
        }
        double m = SupportTriangle.margin(px, py, 3, cop[0], cop[1]);
        return there && m >= margin || stateTime > MOST_SHIFT_WAIT && m > 0;
    }

    /**
     * Where the body must stand before leg {@code l} lifts: {x, y} in the ground frame. Unplanned, where the weight
     * comes down on the weight point ({@link #weightPoint}); with {@code planReach}, the point nearest where the
     * body stands best over its feet (their centre, {@code lead} of the stride ahead) at which the weight comes down
     * inside the triangle of the three feet other than {@code l} by {@code margin}, the foot being proved carries at
     * least {@code proofShare} of it, every foot stays within its leg's reach ({@link LegReach}), and no other foot
     * carries more than 0.9 of what it bore when it was proved or what its leg can hold ({@link LegReach#capacity}) —
     * in that order of precedence, the last given up first when not all can hold ({@link PlanarConstraints}).
     */
    private double[] shiftTarget(int l) {
        return planReach ? plannedShift(l) : weightShift(l);
    }

    /** The body's place that brings the weight down on the weight point ({@link #weightPoint}): {x, y}. */
    private double[] weightShift(int l) {
        double[] t = weightPoint(l);
        double[] o = comOffset();
        return new double[] {t[0] - o[0], t[1] - o[1]};
    }

    /**
     * How far the centre of mass stands off the body's centre, in the ground frame: {x, y} — by the mass model of
     * the legs plus what the soles taught.
     */
    private double[] comOffset() {
        double lx = KeepBalance.comX(sensed.position) + biasX;
        double ly = KeepBalance.comY(sensed.position) + biasY;
        double cos = Math.cos(psi);
        double sin = Math.sin(psi);
        return new double[] {cos * lx - sin * ly, sin * lx + cos * ly};
    }

    /**
     * Where the weight must come down before leg {@code l} lifts, unplanned: inside the triangle of the three others,
     * at the point where the foot being proved carries {@code proofShare} of it and the other two the rest evenly
     * (the centroid when none is being proved). {x, y} in the ground frame.
     */
    private double[] weightPoint(int l) {
        double tx = 0;
        double ty = 0;
        boolean weighted = proving >= 0 && proving != l;
        for (int k = 0; k < LEGS; k++) {
            if (k == l) {
                continue;
            }
            double w = !weighted ? 1.0 / 3 : k == proving ? proofShare : (1 - proofShare) / 2;
            tx += w * gx[k];
            ty += w * gy[k];
        }
        return new double[] {tx, ty};
    }

    /** The planned shift ({@code planReach}); see {@link #shiftTarget}. */
    private double[] plannedShift(int l) {
        double cos = Math.cos(psi);
        double sin = Math.sin(psi);
        double[] o = comOffset();
        double ox = o[0];
        double oy = o[1];
        plan.clear();
        int n = 0;
        for (int k : AROUND) {
            if (k != l) {
                tri[n++] = k;
            }
        }
        boolean weighted = proving >= 0 && proving != l;
        for (int i = 0; i < 3; i++) {
            int k = tri[i];
            int a = tri[(i + 1) % 3];
            int b = tri[(i + 2) % 3];
            // the weight's share on foot k, from the line through the other two: at least the margin inside; the
            // proof share on the foot being proved; at most what k bore when proved or can hold
            double ex = gx[b] - gx[a];
            double ey = gy[b] - gy[a];
            double len = Math.hypot(ex, ey);
            if (len < 1e-6) {
                continue;
            }
            double nx = -ey / len;
            double ny = ex / len;
            double h = nx * (gx[k] - gx[a]) + ny * (gy[k] - gy[a]);
            if (h < 0) {
                nx = -nx;
                ny = -ny;
                h = -h;
            }
            double base = nx * gx[a] + ny * gy[a];
            // nx·(b + o) ≥ base + least  ⇔  −nx·b ≤ nx·o − base − least
            plan.add(-nx, -ny, nx * ox + ny * oy - base - Math.max(margin, leastLoad / DistributeForces.WEIGHT * h), 0);
            if (weighted && k == proving) {
                plan.add(-nx, -ny, nx * ox + ny * oy - base - proofShare * h, 1);
            }
            double most = Math.min(PLANNED_OF_PROVEN * proven[k], capacityAt(k)) / DistributeForces.WEIGHT;
            if (most < 1 && !(weighted && k == proving)) {
                plan.add(nx, ny, base + most * h - nx * ox - ny * oy, 3);
            }
        }
        for (int k = 0; k < LEGS; k++) {
            double[][] w = reach.wedge(k);
            for (double[] row : w) {
                // row·Rᵀ(g − b) ≤ c  ⇔  −(R row)·b ≤ c − (R row)·g
                double ax = cos * row[0] - sin * row[1];
                double ay = sin * row[0] + cos * row[1];
                plan.add(-ax, -ay, row[2] - ax * gx[k] - ay * gy[k], 2);
            }
        }
        double[] centre = feetCentre();
        double[] t = new double[2];
        plan.nearest(centre[0] + cos * lead * stride, centre[1] + sin * lead * stride, t);
        return t;
    }

    /** The load foot {@code k}'s leg can hold where it is commanded to stand now against the body, N. */
    private double capacityAt(int k) {
        double cos = Math.cos(psi);
        double sin = Math.sin(psi);
        double dx = gx[k] - bx;
        double dy = gy[k] - by;
        return LegReach.capacity(k, cos * dx + sin * dy, -sin * dx + cos * dy, gz[k] + lift);
    }

    /** Where the body's centre stands when the feet stand about it as when standing (their centre): {x, y}. */
    private double[] feetCentre() {
        double cx = 0;
        double cy = 0;
        double cos = Math.cos(psi);
        double sin = Math.sin(psi);
        for (int k = 0; k < LEGS; k++) {
            cx += (gx[k] - (cos * homeX[k] - sin * homeY[k])) / LEGS;
            cy += (gy[k] - (sin * homeX[k] + cos * homeY[k])) / LEGS;
        }
        return new double[] {cx, cy};
    }

    /** Moves the body (while all four feet are down) towards where the shift takes it. */
    private void moveBody(double dt) {
        int l = state == State.SHIFT || state == State.UNLOAD || state == State.HOLD ? leg
                : state == State.RESTORE ? proving : -1;
        if (l < 0) {
            speed = 0;
        }
        if (l >= 0) {
            double[] t = shiftTarget(l);
            double dx = t[0] - bx;
            double dy = t[1] - by;
            double d = Math.hypot(dx, dy);
            // the speed that stops the body at the target with the deceleration allowed, no faster than BODY_SPEED,
            // reached with that acceleration: a body jerked into motion makes the lightly loaded feet slide
            double wanted = Math.min(BODY_SPEED, Math.sqrt(2 * BODY_ACCELERATION * d));
            speed = Math.min(wanted, speed + BODY_ACCELERATION * dt);
            if (d > 1e-9) {
                double move = Math.min(d, speed * dt + 0.0002);
                bx += dx / d * move;
                by += dy / d * move;
            }
            psi += Math.max(-TURN_SPEED * dt, Math.min(TURN_SPEED * dt, psiTarget - psi));
        }
        double mean = 0;
        for (int k = 0; k < LEGS; k++) {
            mean += gz[k] / LEGS;
        }
        double wanted = -(height - FOOT_RADIUS) - mean;
        lift += Math.max(-HEIGHT_SPEED * dt, Math.min(HEIGHT_SPEED * dt, wanted - lift));
    }

    /** Learns, slowly and while all feet stand, how far the weight comes down from where the mass model puts it. */
    private void learnBias(double dt) {
        if (state != State.SETTLE && state != State.SHIFT && state != State.LOAD
                || !sensed.centreOfPressure(DistributeForces.WEIGHT * 0.8, cop)) {
            return;
        }
        double ex = cop[0] - KeepBalance.comX(sensed.position);
        double ey = cop[1] - KeepBalance.comY(sensed.position);
        double a = biasKnown ? 1 - Math.exp(-dt / 2.0) : 1;
        biasX += (ex - biasX) * a;
        biasY += (ey - biasY) * a;
        biasKnown = true;
    }

    /** A standing foot whose sensed place drifted {@link #SLIP} m from where it was set, against the others, slid. */
    private void watchSlips(double dt) {
        if (state == State.SETTLE) {
            return;
        }
        double[] drift = standingDrift();
        int n = (int) drift[2];
        if (n < 3) {
            return;
        }
        double rx = drift[0] / n;
        double ry = drift[1] / n;
        for (int k = 0; k < LEGS; k++) {
            if (!standing(k) || k == proving || slipped[k]) {
                continue;
            }
            double[] e = sensedGround(k);
            double s = Math.hypot(e[0] - gx[k] - rx, e[1] - gy[k] - ry);
            slidFor[k] = s - slip0[k] > SLIP ? slidFor[k] + dt : 0;
            if (slidFor[k] >= SLID_FOR) {
                slipped[k] = true;
                slips++;
            }
        }
    }

    /** The standing feet's summed drift from where they were set, along x and y, and how many stand. */
    private double[] standingDrift() {
        double rx = 0;
        double ry = 0;
        int n = 0;
        for (int k = 0; k < LEGS; k++) {
            if (standing(k)) {
                double[] e = sensedGround(k);
                rx += e[0] - gx[k];
                ry += e[1] - gy[k];
                n++;
            }
        }
        return new double[] {rx, ry, n};
    }

    /** Records how far the sensed foot {@code l} stands off its place now, the reference its slip is told from. */
    private void recordSetDown(int l) {
        double[] drift = standingDrift();
        int n = (int) drift[2];
        double[] e = sensedGround(l);
        slip0[l] = n == 0 ? 0 : Math.hypot(e[0] - gx[l] - drift[0] / n, e[1] - gy[l] - drift[1] / n);
        slipped[l] = false;
        slidFor[l] = 0;
    }

    private boolean standing(int k) {
        return !((state == State.SWING && k == leg) || (state == State.RESWING && k == proving));
    }

    /** Foot {@code l}'s sensed place on the ground: the body's planned place plus the sensed foot. */
    private double[] sensedGround(int l) {
        double x = sensed.position[3 * l];
        double y = sensed.position[3 * l + 1];
        return new double[] {bx + Math.cos(psi) * x - Math.sin(psi) * y, by + Math.sin(psi) * x + Math.cos(psi) * y};
    }

    /** Where foot {@code l} is commanded now, on the ground frame. */
    private double[] footGround(int l) {
        return new double[] {gx[l], gy[l]};
    }

    /** The height the ground under a swinging foot is expected at: the mean of the other feet's. */
    private double expectedGround(int l) {
        double s = 0;
        for (int k = 0; k < LEGS; k++) {
            if (k != l) {
                s += gz[k] / 3;
            }
        }
        return s;
    }

    /** The highest of the ground the feet other than {@code l} stand on: a planned swing moves over it. */
    private double highestGround(int l) {
        double s = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < LEGS; k++) {
            if (k != l) {
                s = Math.max(s, gz[k]);
            }
        }
        return s;
    }

    /** The load the distribution asks of foot {@code l} (input {@code sole targets}), else its proof share. */
    private double target(RelationContext c, int l) {
        Value t = SensedFeet.named(c, "sole targets");
        if (t != null && t.length() > l && t.element(l) >= 0) {
            return t.element(l);
        }
        return proofShare * DistributeForces.WEIGHT;
    }

    /** The turn {@code steer} asks for, rad per cycle (0 when not connected). */
    private static double steer(RelationContext c) {
        Value v = SensedFeet.named(c, "steer");
        return v == null || v.length() < 1 ? 0 : v.element(0);
    }

    private void to(State s) {
        state = s;
        stateTime = 0;
    }

    private void write(RelationContext c) {
        double cos = Math.cos(psi);
        double sin = Math.sin(psi);
        for (int l = 0; l < LEGS; l++) {
            boolean swinging = (state == State.SWING && l == leg) || (state == State.RESWING && l == proving);
            double x = swinging ? path.x() : gx[l];
            double y = swinging ? path.y() : gy[l];
            double z = swinging ? path.z() : gz[l];
            double dx = x - bx;
            double dy = y - by;
            feet.set(l, cos * dx + sin * dy, -sin * dx + cos * dy, z + lift);
        }
        c.output("gait feet", feet.value());
        c.output("gait phase", phase().value());
        if (c.outputIndex("slips") >= 0) {
            c.output("slips", Value.of(slips));
        }
        c.report(String.format(Locale.ROOT, "%s leg %d, proving %d, share %.2f", state, leg, proving, share));
    }

    private GaitPhase phase() {
        return switch (state) {
            case SETTLE -> GaitPhase.STANDING;
            case SWING -> new GaitPhase(leg, true, 0, -1, 0);
            case RESWING -> new GaitPhase(proving, true, 0, -1, 0);
            default -> proving >= 0 ? new GaitPhase(proving, false, attempt, unloading, share)
                    : new GaitPhase(leg, false, 0, unloading, share);
        };
    }
}
