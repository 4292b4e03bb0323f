package org.fdnet.roq.sim;

/**
 * Fragile cell {@code cell} (its index in {@link Course#fragileCells()}) breaks at {@code startSeconds} whatever
 * its load: the foot standing on it drops into its pit and that sole's force falls at once — the "sole-force drop"
 * stimulus of {@code bench roq} (b). A real event (a crust giving way under a loaded foot), not a sensor fault.
 *
 * @param startSeconds simulated time it breaks, s (≥ 0)
 * @param cell         which fragile cell (≥ 0; the course must have it)
 */
public record CellBreak(double startSeconds, int cell) implements Stimulus {
    /** Checks the figures; the message names the bad one. */
    public CellBreak {
        if (!(startSeconds >= 0) || Double.isInfinite(startSeconds)) {
            throw new IllegalArgumentException("break time must be >= 0 s, was " + startSeconds);
        }
        if (cell < 0) {
            throw new IllegalArgumentException("break cell must be a fragile cell's index >= 0, was " + cell);
        }
    }

    @Override
    public long endTick() {
        return firstTick() + 1;
    }
}
