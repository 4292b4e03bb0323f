package org.fdnet.viewer.ui;

import java.util.function.LongSupplier;

/**
 * The one time axis every plot of a window shares: the width of the time window, whether it follows the newest
 * value or stays where it was paused (or panned to), and the time cursor. Zooming, panning, pausing or moving
 * the cursor in one plot moves them in all, since each plot draws from this axis at every frame.
 * Read by the painters and written on the event thread; the fields are volatile.
 */
public final class TimeAxis {
    /** No cursor. */
    public static final long NO_CURSOR = Long.MIN_VALUE;

    private volatile LongSupplier newest;
    private volatile long frameEnd = Long.MIN_VALUE;
    private volatile long windowMicros = 10_000_000;
    private volatile boolean paused;
    private volatile long pausedEnd;
    private volatile long cursor = NO_CURSOR;

    /** {@code newest}: the newest value's time (µs), {@link Long#MIN_VALUE} when there is none yet. */
    public TimeAxis(LongSupplier newest) {
        this.newest = newest;
    }

    /** Where the newest value's time comes from (the data the window shows). */
    public void follow(LongSupplier newestTime) {
        newest = newestTime;
        frameEnd = Long.MIN_VALUE;
    }

    /**
     * Takes the newest value's time as the right edge of the next frame: every plot painted until the next tick
     * shows the same window, even while values arrive (a replay at 10×) during the painting of one plot after the
     * other. Called on the event thread before each frame.
     */
    public void tick() {
        frameEnd = newest.getAsLong();
    }

    /** Paused, the view keeps its place while values keep arriving; resumed, it follows the newest again. */
    public void setPaused(boolean pause) {
        if (pause && !paused) {
            pausedEnd = viewEnd();
        }
        paused = pause;
    }

    public boolean paused() {
        return paused;
    }

    /** Multiplies the width of the time window ({@code < 1} zooms in). */
    public void zoom(double factor) {
        windowMicros = Math.max(1_000, Math.min(7L * 24 * 3600 * 1_000_000, (long) (windowMicros * factor)));
    }

    public long windowMicros() {
        return windowMicros;
    }

    public void setWindowMicros(long micros) {
        windowMicros = Math.max(1_000, micros);
    }

    /** Shows {@code from .. to} (µs) and pauses there (history, a replayed range). */
    public void showRange(long from, long to) {
        windowMicros = Math.max(1_000, to - from);
        pausedEnd = to;
        paused = true;
    }

    /** Pans to end at {@code end} (µs), paused there. */
    public void panTo(long end) {
        pausedEnd = end;
        paused = true;
    }

    /** The time (µs) at the right edge of the plots. */
    public long viewEnd() {
        if (paused) {
            return pausedEnd;
        }
        long last = frameEnd != Long.MIN_VALUE ? frameEnd : newest.getAsLong();
        return last == Long.MIN_VALUE ? System.currentTimeMillis() * 1000 : last;
    }

    public long viewStart() {
        return viewEnd() - windowMicros;
    }

    /** The cursor's time (µs), or {@link #NO_CURSOR}. */
    public long cursor() {
        return cursor;
    }

    public void setCursor(long time) {
        cursor = time;
    }
}
