package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.COXA_MASS;
import static org.fdnet.roq.sim.RoqGeometry.FOOT_MASS;
import static org.fdnet.roq.sim.RoqGeometry.HIP_POSITION;
import static org.fdnet.roq.sim.RoqGeometry.LEGS;
import static org.fdnet.roq.sim.RoqGeometry.SHANK_MASS;
import static org.fdnet.roq.sim.RoqGeometry.THIGH_MASS;
import static org.fdnet.roq.sim.RoqGeometry.TOTAL_MASS;

import java.util.Locale;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Keep balance, closed on what RoQ senses: reads the gait's phase {leg about to swing or swinging, in the air, probe
 * attempt} (the plan: which foot lifts next) and, by name, the measured {@code joint angles}, {@code foot forces}
 * and {@code attitude} (the inclinometer's roll and pitch). It shifts the body until the measured centre of pressure
 * of the soles — where the weight comes down, the centre of mass's projection while RoQ stands still — lies over the
 * centroid of the three feet that stay down (their positions by forward kinematics of the joint angles,
 * {@link SensedFeet}), with a time constant {@code tau} s (default 0.25): an integral controller on the measured
 * error, not a model of where the commanded feet put the mass. The inclinometer adds the tip: roll and pitch minus
 * their slow mean ({@code level} s, default 2: the slope RoQ stands on) tell that the body is turning about an edge
 * of its support; the body is shifted up that tilt, {@code tip} m per rad (default 0.3).
 *
 * <p>While the lifted foot probes the ground ({@link ProbeGround}: the phase's probe attempt is non-zero) with
 * {@code press} N (default 0: no leaning), that foot pushes the body up; the three other feet then carry the
 * weight as if the centre of mass stood at c + k (c − foot), k = press / (weight − press). So the body leans
 * towards the probed foot by k / (2 + k) of the way: c and that point lie about as far inside the triangle, and the
 * foot can press its test force without lifting a neighbour off the ground — and should the ground give way, c is
 * still inside the triangle.
 *
 * <p>Outputs: the Data named {@code margin} (when connected) gets the stability margin every firing — the measured
 * centre of pressure's distance to the nearest edge of the support polygon, m, negative outside: the triangle of
 * three feet while a leg is in the air, probing or about to lift, the four feet otherwise; every other output gets
 * the shift as an offset to add to every foot (12 numbers: −dx, −dy, 0 per foot). Also reports the margin
 * ("margin X m", "(below M)" under the parameter {@code margin}, default 0.05 m). Reads no ground truth and no
 * commanded feet.
 */
public class KeepBalance extends Relation {
    /** The feet in order around the body: fl, fr, hr, hl. */
    private static final int[] AROUND = {0, 1, 3, 2};
    private static final double LEG_REST = THIGH_MASS + SHANK_MASS + FOOT_MASS;
    /** RoQ's weight, N. */
    private static final double WEIGHT = TOTAL_MASS * 9.81;
    /** How far the centre of mass moves against the feet when the body moves by 1 over them. */
    static final double FOLLOW = 1 - LEGS * LEG_REST / 2 / TOTAL_MASS;
    /** The farthest the body shifts from its place over the feet, m. */
    private static final double MOST_SHIFT = 0.15;
    /** The fastest the body shifts over its feet, m/s. */
    private static final double MOST_SPEED = 0.25;
    /** The least time between two shifts, s. */
    static final double STEP = 0.0095;

    private final double[] offset = new double[3 * LEGS];
    private final double[] px = new double[LEGS];
    private final double[] py = new double[LEGS];
    private final double[] cop = new double[2];
    private final SensedFeet sensed = new SensedFeet();
    private final double[] unshifted = new double[3 * LEGS];
    private double biasX;
    private double biasY;
    private double tau;
    private double dx;
    private double dy;
    private double last = Double.NaN;
    private double margin;
    private double press;
    private double level;
    private double tip;
    private double meanRoll = Double.NaN;
    private double meanPitch;

    public static final ParameterSpec<Double> TAU = ParameterSpec.number("tau").unit("s").above(0).defaultValue(0.25)
            .describe("the time constant the body is shifted over the support with").live();
    public static final ParameterSpec<Double> MARGIN = ParameterSpec.number("margin").unit("m").defaultValue(0.05)
            .describe("the stability margin below which the report says so").live();
    public static final ParameterSpec<Double> PRESS = ParameterSpec.number("press").unit("N").range(0, Math.round(WEIGHT / 2))
            .defaultValue(0.0).describe("the force a probing foot presses with, leant towards (0: no leaning)").live();
    public static final ParameterSpec<Double> LEVEL = ParameterSpec.number("level").unit("s").above(0).defaultValue(2.0)
            .describe("the time the slope RoQ stands on is averaged over").live();
    public static final ParameterSpec<Double> TIP = ParameterSpec.number("tip").unit("m/rad").range(0, 2).defaultValue(0.3)
            .describe("the shift up the tilt per radian of tip").live();

    @Override
    protected void init(NodeParameters p) {
        tau = TAU.read(p);
        margin = MARGIN.read(p);
        press = PRESS.read(p);
        level = LEVEL.read(p);
        tip = TIP.read(p);
    }

    @Override
    protected void compute(RelationContext c) {
        Value phase = SensedFeet.named(c, "gait phase");
        if (phase == null || phase.length() < 1 || !sensed.read(SensedFeet.named(c, "joint angles"),
                SensedFeet.named(c, "foot forces"), SensedFeet.named(c, "attitude"))) {
            return;
        }
        int next = (int) phase.element(0);
        if (next < 0 || next >= LEGS) {
            return;
        }
        boolean up = phase.length() > 1 && phase.element(1) > 0.5 || phase.length() > 2 && phase.element(2) > 0.5;
        double[] feet = sensed.position;
        double now = c.seconds();
        if (!Double.isNaN(last) && now - last < STEP) {
            return; // the joint angles change every tick: act on them every 10 ms
        }
        double dt = Double.isNaN(last) ? 0 : now - last;
        last = now;
        // the measured feet stand where the shift put them: undo it to see the posture the gait gave
        for (int leg = 0; leg < LEGS; leg++) {
            unshifted[3 * leg] = feet[3 * leg] + dx;
            unshifted[3 * leg + 1] = feet[3 * leg + 1] + dy;
        }
        // where the centre of mass must go: over the centroid of the three feet that stay down
        double cx = 0;
        double cy = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            if (leg != next) {
                cx += unshifted[3 * leg] / 3;
                cy += unshifted[3 * leg + 1] / 3;
            }
        }
        boolean probing = phase.length() > 2 && phase.element(2) > 0.5;
        if (probing && press > 0) {
            // the probed foot pushes the body up with `press`: the other three feet then carry the weight as if
            // it stood at c + lever (c − foot), lever = press / (weight − press). Move the centre of mass towards
            // the probed foot by t = lever / (2 + lever) of the way, so both c (should the ground give way) and
            // that point (while the foot presses) lie about as far inside the triangle.
            double lever = press / (WEIGHT - press);
            double t = lever / (2 + lever);
            cx += t * (unshifted[3 * next] - cx);
            cy += t * (unshifted[3 * next + 1] - cy);
        }
        // the soles say where the weight really comes down: learn, slowly, how far that lies from the mass model
        double slow = 1 - Math.exp(-dt / level);
        if (sensed.centreOfPressure(WEIGHT / 2, cop)) {
            biasX += (cop[0] - comX(feet) - biasX) * slow;
            biasY += (cop[1] - comY(feet) - biasY) * slow;
        }
        double tx = (cx - comX(unshifted) - biasX) / FOLLOW;
        double ty = (cy - comY(unshifted) - biasY) / FOLLOW;
        Value attitude = SensedFeet.named(c, "attitude");
        if (attitude != null && attitude.length() >= 2) {
            // roll > 0: the left side (y > 0) up; pitch > 0: the nose (x > 0) down. The body's low side is where the
            // tip (attitude minus its slow mean, the ground's slope) points: shift the body the other way.
            double roll = attitude.element(0);
            double pitch = attitude.element(1);
            if (Double.isNaN(meanRoll)) {
                meanRoll = roll;
                meanPitch = pitch;
            }
            meanRoll += (roll - meanRoll) * slow;
            meanPitch += (pitch - meanPitch) * slow;
            tx -= tip * (pitch - meanPitch) / FOLLOW;
            ty += tip * (roll - meanRoll) / FOLLOW;
        }
        double a = 1 - Math.exp(-dt / tau);
        // no faster than MOST_SPEED: a body flung at the new triangle makes the feet slip and the body rock
        double step = MOST_SPEED * dt;
        dx = clamp(dx + clamp((tx - dx) * a, step), MOST_SHIFT);
        dy = clamp(dy + clamp((ty - dy) * a, step), MOST_SHIFT);
        for (int leg = 0; leg < LEGS; leg++) {
            offset[3 * leg] = -dx;
            offset[3 * leg + 1] = -dy;
            offset[3 * leg + 2] = 0;
        }
        int n = 0;
        for (int leg : AROUND) {
            if (!(up && leg == next)) {
                px[n] = feet[3 * leg];
                py[n] = feet[3 * leg + 1];
                n++;
            }
        }
        double m = SupportTriangle.margin(px, py, n, cop[0], cop[1]);
        int marginOut = c.outputIndex("margin");
        for (int i = 0; i < c.outputCount(); i++) {
            c.output(i, i == marginOut ? Value.of(m) : Value.ofDoubles(offset));
        }
        c.report(String.format(Locale.ROOT, "margin %.3f m%s", m, m < margin ? " (below " + margin + ")" : ""));
    }

    /** The centre of mass's x in the body frame, estimated from the feet: body at its centre, each coxa at its hip, the rest of each leg halfway between hip and foot. */
    static double comX(double[] feet) {
        double s = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            double hip = HIP_POSITION[leg][0];
            s += COXA_MASS * hip + LEG_REST * (hip + feet[3 * leg]) / 2;
        }
        return s / TOTAL_MASS;
    }

    static double comY(double[] feet) {
        double s = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            double hip = HIP_POSITION[leg][1];
            s += COXA_MASS * hip + LEG_REST * (hip + feet[3 * leg + 1]) / 2;
        }
        return s / TOTAL_MASS;
    }

    private static double clamp(double v, double limit) {
        return Math.max(-limit, Math.min(limit, v));
    }
}
