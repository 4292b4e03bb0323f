package org.fdnet.roq.sim;

/**
 * A block standing on the terrain that gives way under load: when the normal force on it stays above
 * {@code strength} for {@link #BREAK_HOLD_SECONDS}, it breaks (drops out of the way, loses its collisions) and is
 * reported in every later snapshot ({@link SensorSnapshot#isCellBroken(int)}). A probing tap (brief, or below the
 * strength) leaves it standing; a foot carrying the robot's weight breaks it.
 *
 * @param x        centre, m (course frame)
 * @param y        centre, m
 * @param sizeX    extent along x, m
 * @param sizeY    extent along y, m
 * @param height   how far its top stands above the terrain beneath it, m
 * @param strength normal force it bears indefinitely, N
 */
public record FragileCell(double x, double y, double sizeX, double sizeY, double height, double strength) {
    /** How long the load must stay above the strength before the cell breaks, s. */
    public static final double BREAK_HOLD_SECONDS = 0.1;
    /** The tallest fragile block, m: the robot's legs clear 0.3 m of rubble at most. */
    public static final double MAX_HEIGHT = 0.3;

    /** Checks the figures; the message names the bad one. */
    public FragileCell {
        if (!(sizeX > 0) || !(sizeY > 0)) {
            throw new IllegalArgumentException("fragile cell size must be > 0, was " + sizeX + " x " + sizeY);
        }
        if (!(height > 0 && height <= MAX_HEIGHT)) {
            // a taller block made the heightfield's range overflow to infinity (a fuzz finding)
            throw new IllegalArgumentException("fragile cell height must be above 0 and at most " + MAX_HEIGHT
                    + " m, was " + height);
        }
        if (!(strength > 0)) {
            throw new IllegalArgumentException("fragile cell strength must be > 0 N, was " + strength);
        }
        if (!Double.isFinite(x) || !Double.isFinite(y)) {
            throw new IllegalArgumentException("fragile cell position must be finite, was " + x + ", " + y);
        }
    }

    /** How far (px, py) lies outside this cell's footprint, m (0 on it). */
    public double distanceOutside(double px, double py) {
        return Math.hypot(Math.max(0, Math.abs(px - x) - sizeX / 2), Math.max(0, Math.abs(py - y) - sizeY / 2));
    }

    /** Whether (px, py) lies on this cell. */
    public boolean contains(double px, double py) {
        return Math.abs(px - x) <= sizeX / 2 && Math.abs(py - y) <= sizeY / 2;
    }
}
