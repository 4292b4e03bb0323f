package org.fdnet.corba.bench;

/**
 * Counts the values of a sequence stream as they arrive: each arrival is one, whatever number it carries
 * (so a lost value is missing from the count, not hidden behind a later number), plus the arrivals that
 * did not carry the next number (out of order, repeated or after a gap), and the arrivals in each window
 * of time since {@link #start}, so a stall shows as a window with few arrivals. Thread-safe.
 */
public final class ArrivalCount {
    private final long windowNanos;
    private long[] perWindow = new long[16];
    private long startNanos;
    private long received;
    private long unexpected;
    private long next;
    private long lastArrivalNanos;

    public ArrivalCount(long windowNanos) {
        if (windowNanos <= 0) {
            throw new IllegalArgumentException("window must be positive, was " + windowNanos + " ns");
        }
        this.windowNanos = windowNanos;
    }

    /** Time zero of the windows: when the first value is written. */
    public synchronized void start(long nanoTime) {
        startNanos = nanoTime;
        lastArrivalNanos = nanoTime;
    }

    /** One value arrived at {@code nanoTime}, carrying {@code sequence}. */
    public synchronized void arrived(long sequence, long nanoTime) {
        received++;
        if (sequence != next) {
            unexpected++;
        }
        next = sequence + 1;
        lastArrivalNanos = nanoTime;
        int window = (int) Math.max(0, (nanoTime - startNanos) / windowNanos);
        if (window >= perWindow.length) {
            perWindow = java.util.Arrays.copyOf(perWindow, Math.max(window + 1, perWindow.length * 2));
        }
        perWindow[window]++;
    }

    public synchronized long received() {
        return received;
    }

    /** Arrivals that did not carry the number after the previous one's. */
    public synchronized long unexpected() {
        return unexpected;
    }

    /** Seconds from {@link #start} to the last arrival. */
    public synchronized double seconds() {
        return (lastArrivalNanos - startNanos) / 1e9;
    }

    /** Arrivals per window, from the first window to the last one with an arrival. */
    public synchronized long[] perWindow() {
        int last = perWindow.length - 1;
        while (last > 0 && perWindow[last] == 0) {
            last--;
        }
        return java.util.Arrays.copyOf(perWindow, last + 1);
    }
}
