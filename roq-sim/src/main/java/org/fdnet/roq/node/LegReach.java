package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.COXA_LENGTH;
import static org.fdnet.roq.sim.RoqGeometry.HIP_POSITION;
import static org.fdnet.roq.sim.RoqGeometry.JOINT_MAX;
import static org.fdnet.roq.sim.RoqGeometry.JOINT_MIN;
import static org.fdnet.roq.sim.RoqGeometry.THIGH_LENGTH;
import static org.fdnet.roq.sim.RoqGeometry.maxJointTorque;

/**
 * Where one of RoQ's feet can stand, seen from its hip, and how much it can carry there, from the model's geometry
 * ({@link org.fdnet.roq.sim.RoqGeometry}): the hip's yaw range less a margin makes a wedge opening outward from the
 * hip, in which a foot standing {@code out} m out from the hip may be at most {@link #along} ahead of or behind it;
 * a foot must also stand at least {@code inward} m out (nearer under the hip the knee folds at full torque). The
 * load a leg carries is the vertical sole force its lift and knee motors hold at their torque limit
 * ({@link #capacity}), the joint angles from {@link LegInverseKinematics#solve}.
 *
 * <p>The wedge is linear in the foot's place, so a planner can state "foot k stays within reach" as half-planes
 * ({@link #wedge}).
 */
final class LegReach {
    private final double tanYaw;
    private final double inward;

    /**
     * A reach of the hip's yaw range less {@code yawMargin} rad either way, the foot at least {@code inward} m out
     * from the hip.
     */
    LegReach(double yawMargin, double inward) {
        double yaw = Math.min(JOINT_MAX[0], -JOINT_MIN[0]) - yawMargin;
        if (yaw <= 0) {
            throw new IllegalArgumentException("a yaw margin of " + yawMargin + " rad leaves the hip no range");
        }
        this.tanYaw = Math.tan(yaw);
        this.inward = inward;
    }

    /** How far ahead of or behind its hip a foot standing {@code out} m out from it may be, m (0 when too far in). */
    double along(double out) {
        return out < inward ? 0 : out * tanYaw;
    }

    /** Whether leg {@code leg}'s foot at ({@code x}, {@code y}) in the body frame is within reach. */
    boolean reaches(int leg, double x, double y) {
        double a = x - HIP_POSITION[leg][0];
        double o = outward(leg, y);
        return o >= inward && Math.abs(a) <= o * tanYaw;
    }

    /** How far leg {@code leg}'s foot at body-frame {@code y} stands out from its hip, m. */
    static double outward(int leg, double y) {
        return Math.signum(HIP_POSITION[leg][1]) * (y - HIP_POSITION[leg][1]);
    }

    /**
     * The reach of leg {@code leg} as three half-planes on the foot's place (x, y) in the body frame: row i of the
     * result is {a, b, c} with a·x + b·y ≤ c — the wedge's front side, its back side, and the least distance out.
     */
    double[][] wedge(int leg) {
        double hx = HIP_POSITION[leg][0];
        double hy = HIP_POSITION[leg][1];
        double side = Math.signum(hy);
        // along = x − hx, out = side·(y − hy): along − tan·out ≤ 0, −along − tan·out ≤ 0, −out ≤ −inward
        return new double[][] {
                {1, -tanYaw * side, hx - tanYaw * side * hy},
                {-1, -tanYaw * side, -hx - tanYaw * side * hy},
                {0, -side, -inward - side * hy}};
    }

    /**
     * The most vertical sole force leg {@code leg} holds with its foot at ({@code x}, {@code y}, {@code z}) in the
     * body frame, N: the lift motor holds the force at the foot's distance out from the lift axis, the knee at its
     * distance out from the knee; the smaller of the two limits.
     */
    static double capacity(int leg, double x, double y, double z) {
        double[] angles = new double[3];
        LegInverseKinematics.solve(leg, x, y, z, angles, 0);
        double out = Math.hypot(x - HIP_POSITION[leg][0], y - HIP_POSITION[leg][1]);
        double fromLift = Math.abs(out - COXA_LENGTH);
        double fromKnee = Math.abs(out - COXA_LENGTH - THIGH_LENGTH * Math.cos(angles[1]));
        double arm = Math.max(fromLift, fromKnee);
        return arm < 1e-6 ? Double.MAX_VALUE : maxJointTorque() / arm;
    }
}
