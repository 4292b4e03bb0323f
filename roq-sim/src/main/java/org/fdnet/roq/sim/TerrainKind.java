package org.fdnet.roq.sim;

/** The ground of a {@link Course}. */
public enum TerrainKind {
    /** Level ground at height 0. */
    FLAT,
    /** Level up to x = 0, then rising along +x at {@link Course#slopeDegrees()}. */
    SLOPE,
    /** Square blocks of {@link Course#rubbleBlock()} with seeded random heights up to {@link Course#rubbleHeight()}. */
    RUBBLE
}
