package org.fdnet.roq.sim;

/**
 * An external horizontal push on RoQ's body: a constant force at its centre of mass ({@code xfrc_applied}) from
 * {@code startSeconds} for {@code durationSeconds}, pointing along {@code directionDegrees} in the course frame
 * (0 = +x, forward along the course; 90 = +y, to the left).
 *
 * @param startSeconds     simulated time it starts, s (≥ 0)
 * @param durationSeconds  how long it lasts, s (at least one tick, 1 ms; at most 60 s)
 * @param forceNewtons     its size, N (0 < force ≤ 2000)
 * @param directionDegrees which way it pushes, degrees about +z from +x
 */
public record Push(double startSeconds, double durationSeconds, double forceNewtons, double directionDegrees)
        implements Stimulus {
    /** Largest push accepted, N (about ten times RoQ's weight). */
    public static final double MAX_FORCE = 2000;

    /** Checks the figures; the message names the bad one. */
    public Push {
        if (!(startSeconds >= 0) || Double.isInfinite(startSeconds)) {
            throw new IllegalArgumentException("push start must be a time >= 0 s, was " + startSeconds);
        }
        if (!(durationSeconds >= RoqGeometry.TIMESTEP && durationSeconds <= 60)) {
            throw new IllegalArgumentException("push duration must be " + RoqGeometry.TIMESTEP + "..60 s, was "
                    + durationSeconds);
        }
        if (!(forceNewtons > 0 && forceNewtons <= MAX_FORCE)) {
            throw new IllegalArgumentException("push force must be > 0 and <= " + MAX_FORCE + " N, was " + forceNewtons);
        }
        if (!Double.isFinite(directionDegrees)) {
            throw new IllegalArgumentException("push direction must be finite degrees, was " + directionDegrees);
        }
    }

    @Override
    public long endTick() {
        return firstTick() + Math.max(1, Math.round(durationSeconds / RoqGeometry.TIMESTEP));
    }

    /** The force's x component in the course frame, N. */
    public double forceX() {
        return forceNewtons * Math.cos(Math.toRadians(directionDegrees));
    }

    /** The force's y component in the course frame, N. */
    public double forceY() {
        return forceNewtons * Math.sin(Math.toRadians(directionDegrees));
    }
}
