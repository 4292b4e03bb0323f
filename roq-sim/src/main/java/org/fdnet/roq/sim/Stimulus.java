package org.fdnet.roq.sim;

/**
 * Something done to RoQ from outside at a set simulated time — the disturbances that show whether its network
 * reacts: a {@link Push} on the body or a {@link CellBreak} under a foot. Given in a course file (so a course can
 * carry them) or through {@link RoqSimulator#stimulate}; the C tick applies them, so stepped runs stay reproducible.
 */
public sealed interface Stimulus permits Push, CellBreak {
    /** Simulated time at which it starts, s. */
    double startSeconds();

    /** The first tick it acts in (the snapshot of the tick after shows it). */
    default long firstTick() {
        return Math.round(startSeconds() / RoqGeometry.TIMESTEP);
    }

    /** The tick after the last one it acts in. */
    long endTick();
}
