package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.JOINTS;
import static org.fdnet.roq.sim.RoqGeometry.JOINTS_PER_LEG;
import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Where RoQ's feet are and which of them bear load, from what RoQ senses: the feet's centres by forward kinematics
 * of the measured joint angles, turned by the inclinometer's roll and pitch into the level frame that turns with the
 * body's heading (x ahead, y to the left, z up: seen from above, as the weight sees them), and the soles' forces. Shared by the closed-loop Relations
 * ({@link KeepBalance}, {@link HoldCourse}); it never reads ground truth.
 */
final class SensedFeet {
    /** The value of the input called {@code name}, or null when it is not connected or not there. */
    static Value named(RelationContext c, String name) {
        return c.inputIndex(name) >= 0 ? c.input(name) : null;
    }

    /** x, y, z of each foot in the level frame, m. */
    final double[] position = new double[3 * LEGS];
    /** Each sole's force, N. */
    final double[] force = new double[LEGS];
    private final double[] foot = new double[3];

    /**
     * Reads {@code angles} (12), {@code forces} (4) and {@code attitude} (roll, pitch; when missing, the body is taken
     * as level); false (nothing changed) when angles or forces are missing or short.
     */
    boolean read(Value angles, Value forces, Value attitude) {
        if (angles == null || forces == null || angles.length() < JOINTS || forces.length() < LEGS) {
            return false;
        }
        boolean tilt = attitude != null && attitude.length() >= 2;
        double roll = tilt ? attitude.element(0) : 0;
        double pitch = tilt ? attitude.element(1) : 0;
        double cr = Math.cos(roll);
        double sr = Math.sin(roll);
        double cp = Math.cos(pitch);
        double sp = Math.sin(pitch);
        for (int leg = 0; leg < LEGS; leg++) {
            int j = leg * JOINTS_PER_LEG;
            RoqGeometry.footInBody(leg, angles.element(j), angles.element(j + 1), angles.element(j + 2), foot);
            // roll > 0 lifts the left side (y > 0), pitch > 0 lowers the nose (x > 0)
            position[3 * leg] = cp * foot[0] + sp * sr * foot[1] + sp * cr * foot[2];
            position[3 * leg + 1] = cr * foot[1] - sr * foot[2];
            position[3 * leg + 2] = -sp * foot[0] + cp * sr * foot[1] + cp * cr * foot[2];
            force[leg] = Math.max(0, forces.element(leg));
        }
        return true;
    }

    /** The centre of pressure of the soles in the body frame {x, y} into {@code out}; false when they bear under {@code least} N. */
    boolean centreOfPressure(double least, double[] out) {
        double sum = 0;
        double x = 0;
        double y = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            sum += force[leg];
            x += force[leg] * position[3 * leg];
            y += force[leg] * position[3 * leg + 1];
        }
        if (sum < least) {
            return false;
        }
        out[0] = x / sum;
        out[1] = y / sum;
        return true;
    }
}
