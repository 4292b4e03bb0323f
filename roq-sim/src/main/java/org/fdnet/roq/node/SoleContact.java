package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import org.fdnet.runtime.Value;

/**
 * Lift-off and touchdown detection from the sole force sensors: each sole's force as a running mean over
 * {@value #SMOOTHING} s (the contact chatters), and whether a foot has left the ground (under {@code free} N) or
 * found it (at least {@code touch} N).
 */
final class SoleContact {
    /** Time constant of the running mean, s. */
    static final double SMOOTHING = 0.03;

    private final double[] force = {Double.NaN, Double.NaN, Double.NaN, Double.NaN};
    private final double free;
    private final double touch;

    SoleContact(double free, double touch) {
        this.free = free;
        this.touch = touch;
    }

    /** Takes one reading of the four soles ({@code forces}, N), {@code dt} s after the last; false when missing. */
    boolean read(Value forces, double dt) {
        if (forces == null || forces.length() < LEGS) {
            return false;
        }
        double a = 1 - Math.exp(-dt / SMOOTHING);
        for (int leg = 0; leg < LEGS; leg++) {
            double raw = Math.max(0, forces.element(leg));
            force[leg] = Double.isNaN(force[leg]) ? raw : force[leg] + (raw - force[leg]) * a;
        }
        return true;
    }

    /** The sole's running mean, N (0 before the first reading). */
    double force(int leg) {
        return Double.isNaN(force[leg]) ? 0 : force[leg];
    }

    /** Whether the foot carries nothing: it has left the ground. */
    boolean liftedOff(int leg) {
        return force(leg) < free;
    }

    /** Whether the foot has found the ground. */
    boolean touchedDown(int leg) {
        return force(leg) >= touch;
    }
}
