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
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Keep balance: reads the gait's feet (12 numbers, body frame) and its phase {leg about to swing or swinging,
 * in the air, probe attempt}, and shifts the body so that the centre of mass comes over the centroid of the
 * support triangle of the three other feet — smoothly, with a time constant {@code tau} s (default 0.25). The
 * centre of mass is estimated from the feet: the body's mass at its centre, each coxa at its hip, the rest of
 * each leg halfway between hip and foot.
 *
 * <p>While the lifted foot probes the ground ({@link ProbeGround}: the phase's probe attempt is non-zero) with
 * {@code press} N (default 0: no leaning), that foot pushes the body up; the three other feet then carry the
 * weight as if the centre of mass stood at c + k (c − foot), k = press / (weight − press). So the body leans
 * towards the probed foot by k / (2 + k) of the way: c and that point lie about as far inside the triangle, and the
 * foot can press its test force without lifting a neighbour off the ground — and should the ground give way, c is
 * still inside the triangle.
 *
 * <p>Outputs: the Data named {@code margin} (when connected) gets the stability margin every firing — the
 * estimated centre of mass's distance to the nearest edge of the support polygon, m, negative outside: the
 * triangle of three feet while a leg is in the air or probing, the four feet otherwise; every other output gets
 * the shift as an offset to add to every foot (12 numbers: −dx, −dy, 0 per foot). Also reports the margin
 * ("margin X m", "(below M)" under the parameter {@code margin}, default 0.05 m).
 */
public class KeepBalance extends Relation {
    /** The feet in order around the body: fl, fr, hr, hl. */
    private static final int[] AROUND = {0, 1, 3, 2};
    private static final double LEG_REST = THIGH_MASS + SHANK_MASS + FOOT_MASS;
    /** RoQ's weight, N. */
    private static final double WEIGHT = TOTAL_MASS * 9.81;
    /** How far the centre of mass moves against the feet when the body moves by 1 over them. */
    private static final double FOLLOW = 1 - LEGS * LEG_REST / 2 / TOTAL_MASS;

    private final double[] offset = new double[3 * LEGS];
    private final double[] px = new double[LEGS];
    private final double[] py = new double[LEGS];
    /** The three feet that stay down: x, y of each. */
    private final double[] tri = new double[6];
    private double tau;
    private double dx;
    private double dy;
    private double last = Double.NaN;
    private double margin;
    private double press;

    @Override
    protected void init(NodeParameters p) {
        tau = p.doubleValue("tau", 0.25);
        margin = p.doubleValue("margin", 0.05);
        if (tau <= 0) {
            throw p.invalid("tau", "must be more than 0 s, was " + tau);
        }
        press = p.doubleValue("press", 0);
        if (press < 0 || press > WEIGHT / 2) {
            throw p.invalid("press", "must lie between 0 and " + Math.round(WEIGHT / 2) + " N, was " + press);
        }
    }

    @Override
    protected void compute(RelationContext c) {
        Value feet = c.input(0);
        Value phase = c.input(1);
        if (feet == null || phase == null || feet.length() != 3 * LEGS || phase.length() < 1) {
            return;
        }
        int next = (int) phase.element(0);
        boolean up = phase.length() > 1 && phase.element(1) > 0.5 || phase.length() > 2 && phase.element(2) > 0.5;
        // where the centre of mass must go: over the centroid of the three feet that stay down
        int k = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            if (leg != next) {
                tri[2 * k] = feet.element(3 * leg);
                tri[2 * k + 1] = feet.element(3 * leg + 1);
                k++;
            }
        }
        double cx = (tri[0] + tri[2] + tri[4]) / 3;
        double cy = (tri[1] + tri[3] + tri[5]) / 3;
        boolean probing = phase.length() > 2 && phase.element(2) > 0.5 && next >= 0 && next < LEGS;
        if (probing && press > 0) {
            // the probed foot pushes the body up with `press`: the other three feet then carry the weight as if
            // it stood at c + lever (c − foot), lever = press / (weight − press). Move the centre of mass towards
            // the probed foot by t = lever / (2 + lever) of the way, so both c (should the ground give way) and
            // that point (while the foot presses) lie about as far inside the triangle.
            double lever = press / (WEIGHT - press);
            double t = lever / (2 + lever);
            cx += t * (feet.element(3 * next) - cx);
            cy += t * (feet.element(3 * next + 1) - cy);
        }
        // shifting the body by d moves the support by −d in the body frame and the legs' share of the mass by −d/2
        double tx = (cx - comX(feet, 0)) / FOLLOW;
        double ty = (cy - comY(feet, 0)) / FOLLOW;
        double now = c.seconds();
        double dt = Double.isNaN(last) ? 0 : Math.max(0, now - last);
        last = now;
        double a = 1 - Math.exp(-dt / tau);
        dx += (tx - dx) * a;
        dy += (ty - dy) * a;
        for (int leg = 0; leg < LEGS; leg++) {
            offset[3 * leg] = -dx;
            offset[3 * leg + 1] = -dy;
            offset[3 * leg + 2] = 0;
        }
        // the margin of the posture the legs are given: the feet moved by −(dx, dy), the centre of mass with them
        int n = 0;
        for (int leg : AROUND) {
            if (!(up && leg == next)) {
                px[n] = feet.element(3 * leg) - dx;
                py[n] = feet.element(3 * leg + 1) - dy;
                n++;
            }
        }
        double m = SupportTriangle.margin(px, py, n, comX(feet, dx), comY(feet, dy));
        int marginOut = c.outputIndex("margin");
        for (int i = 0; i < c.outputCount(); i++) {
            c.output(i, i == marginOut ? Value.of(m) : Value.ofDoubles(offset));
        }
        c.report(String.format(Locale.ROOT, "margin %.3f m%s", m, m < margin ? " (below " + margin + ")" : ""));
    }

    /** The centre of mass's x in the body frame for these feet moved by −shift. */
    private static double comX(Value feet, double shift) {
        double s = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            double hip = HIP_POSITION[leg][0];
            s += COXA_MASS * hip + LEG_REST * (hip + feet.element(3 * leg) - shift) / 2;
        }
        return s / TOTAL_MASS;
    }

    private static double comY(Value feet, double shift) {
        double s = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            double hip = HIP_POSITION[leg][1];
            s += COXA_MASS * hip + LEG_REST * (hip + feet.element(3 * leg + 1) - shift) / 2;
        }
        return s / TOTAL_MASS;
    }
}
