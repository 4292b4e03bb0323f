package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import org.fdnet.runtime.Value;

/**
 * A view of the twelve numbers the robot's Datas carry for its feet — x, y, z of each foot in leg order fl, fr, hl,
 * hr — by leg and axis, so no Relation indexes {@code 3 * leg + 1} by hand. It owns its array; {@link #value()} copies
 * it out.
 */
public final class Feet {
    /** Numbers per foot. */
    public static final int AXES = 3;
    /** Numbers in all. */
    public static final int LENGTH = AXES * LEGS;

    private final double[] xyz = new double[LENGTH];

    /** The feet in {@code v} (12 numbers), or null when it is missing or of another length. */
    public static Feet of(Value v) {
        if (v == null || v.length() != LENGTH) {
            return null;
        }
        Feet f = new Feet();
        for (int i = 0; i < LENGTH; i++) {
            f.xyz[i] = v.element(i);
        }
        return f;
    }

    public double x(int leg) {
        return xyz[AXES * leg];
    }

    public double y(int leg) {
        return xyz[AXES * leg + 1];
    }

    public double z(int leg) {
        return xyz[AXES * leg + 2];
    }

    /** Sets foot {@code leg} to (x, y, z). */
    public void set(int leg, double x, double y, double z) {
        xyz[AXES * leg] = x;
        xyz[AXES * leg + 1] = y;
        xyz[AXES * leg + 2] = z;
    }

    public void setZ(int leg, double z) {
        xyz[AXES * leg + 2] = z;
    }

    /** Every number to 0. */
    public void clear() {
        java.util.Arrays.fill(xyz, 0);
    }

    /** The twelve numbers as a Value. */
    public Value value() {
        return Value.ofDoubles(xyz.clone());
    }
}
