package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.*;

import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Inverse kinematics of RoQ's four legs: reads the feet's wanted centres in the body frame (12 numbers,
 * {x, y, z} × fl, fr, hl, hr; the first input that is present) and writes the 12 joint angles that put them
 * there (the inverse of {@link org.fdnet.roq.sim.RoqGeometry#footInBody}), knee bent backwards as in the
 * standing pose. A foot out of reach is placed as far as the leg reaches towards it and reported; angles are
 * clamped to the joint limits.
 */
public class LegInverseKinematics extends Relation {
    private final double[] angles = new double[JOINTS];

    @Override
    protected void compute(RelationContext c) {
        Value feet = null;
        for (int i = 0; i < c.inputCount() && feet == null; i++) {
            feet = c.input(i);
        }
        if (feet == null || feet.length() != 3 * LEGS) {
            c.report(feet == null ? "no feet to place" : "feet need 12 numbers, got " + feet.length());
            return;
        }
        boolean clipped = false;
        for (int leg = 0; leg < LEGS; leg++) {
            clipped |= solve(leg, feet.element(3 * leg), feet.element(3 * leg + 1), feet.element(3 * leg + 2),
                    angles, 3 * leg);
        }
        c.report(clipped ? "a foot out of reach" : "ok");
        c.outputAll(Value.ofDoubles(angles));
    }

    /** Writes leg {@code leg}'s yaw, lift, knee for a foot at (x, y, z) into {@code out[at..at+2]}; true when clipped. */
    static boolean solve(int leg, double x, double y, double z, double[] out, int at) {
        double dx = x - HIP_POSITION[leg][0];
        double dy = y - HIP_POSITION[leg][1];
        double yaw = normalise(Math.atan2(dy, dx) - HIP_YAW_OFFSET[leg]);
        double r = Math.hypot(dx, dy) - COXA_LENGTH;
        double h = z - HIP_POSITION[leg][2];
        double d2 = r * r + h * h;
        double cosKnee = (d2 - THIGH_LENGTH * THIGH_LENGTH - SHANK_LENGTH * SHANK_LENGTH)
                / (2 * THIGH_LENGTH * SHANK_LENGTH);
        boolean clipped = cosKnee < -1 || cosKnee > 1;
        double knee = Math.acos(Math.max(-1, Math.min(1, cosKnee)));
        double lift = Math.atan2(h, r) + Math.atan2(SHANK_LENGTH * Math.sin(knee), THIGH_LENGTH + SHANK_LENGTH * Math.cos(knee));
        int base = leg * JOINTS_PER_LEG;
        out[at] = clamp(yaw, jointMin(base), jointMax(base));
        out[at + 1] = clamp(lift, jointMin(base + 1), jointMax(base + 1));
        out[at + 2] = clamp(knee, jointMin(base + 2), jointMax(base + 2));
        return clipped || out[at] != yaw || out[at + 1] != lift || out[at + 2] != knee;
    }

    private static double normalise(double a) {
        return Math.atan2(Math.sin(a), Math.cos(a));
    }

    private static double clamp(double v, double lo, double hi) {
        return Math.max(lo, Math.min(hi, v));
    }
}
