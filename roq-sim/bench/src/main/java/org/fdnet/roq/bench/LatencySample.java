package org.fdnet.roq.bench;

import java.util.Arrays;
import java.util.Locale;

/** Latencies in ticks (1 ms each), collected and summarised as p50 / p99 / max (nearest rank). */
final class LatencySample {
    private long[] ticks = new long[64];
    private int count;

    void add(long latencyTicks) {
        if (count == ticks.length) {
            ticks = Arrays.copyOf(ticks, count * 2);
        }
        ticks[count++] = latencyTicks;
    }

    /** Adds every sample of this one to {@code other}. */
    void addAllTo(LatencySample other) {
        for (int i = 0; i < count; i++) {
            other.add(ticks[i]);
        }
    }

    int count() {
        return count;
    }

    /** The nearest-rank percentile, ticks; −1 with no samples. */
    long percentile(double p) {
        if (count == 0) {
            return -1;
        }
        long[] sorted = Arrays.copyOf(ticks, count);
        Arrays.sort(sorted);
        int rank = (int) Math.ceil(p / 100.0 * count);
        return sorted[Math.max(0, Math.min(count - 1, rank - 1))];
    }

    long max() {
        return percentile(100);
    }

    /** "p50 1 ms, p99 2 ms, max 3 ms over 40", or "no samples". */
    String summary() {
        return count == 0 ? "no samples" : String.format(Locale.ROOT, "p50 %d ms, p99 %d ms, max %d ms over %,d",
                percentile(50), percentile(99), max(), count);
    }
}
