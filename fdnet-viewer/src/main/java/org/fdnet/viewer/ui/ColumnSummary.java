package org.fdnet.viewer.ui;

import java.util.Arrays;
import org.fdnet.viewer.data.Series;

/**
 * One series reduced to the plot's pixel columns in one pass over its visible samples: per column the
 * first, last, smallest and largest value, plus the last value before the window and the first after it
 * (so the line reaches the edges). Drawing then costs at most four points per column, whatever the sample
 * rate, and each segment joins neighbouring values (no full-height zig-zags). Reused frame after frame.
 */
final class ColumnSummary {
    private double[] first = new double[0];
    private double[] last = new double[0];
    private double[] min = new double[0];
    private double[] max = new double[0];
    private boolean[] used = new boolean[0];
    private int width;
    private double before;
    private double after;
    private boolean hasBefore;
    private boolean hasAfter;
    private long newest;

    /** Summarises the samples of {@code s} in {@code start .. end} over {@code w} columns. */
    void summarise(Series s, long start, long end, int w) {
        if (first.length < w) {
            first = new double[w];
            last = new double[w];
            min = new double[w];
            max = new double[w];
            used = new boolean[w];
        }
        width = w;
        Arrays.fill(used, 0, w, false);
        hasBefore = false;
        hasAfter = false;
        newest = Long.MIN_VALUE;
        double perMicro = (w - 1) / (double) Math.max(1, end - start);
        s.visit(start, end, (t, v) -> {
            if (!Double.isFinite(v)) {
                return;
            }
            if (t < start) {
                before = v;
                hasBefore = true;
            } else if (t > end) {
                if (!hasAfter) {
                    after = v;
                    hasAfter = true;
                }
            } else {
                int x = (int) ((t - start) * perMicro);
                if (!used[x]) {
                    used[x] = true;
                    first[x] = v;
                    min[x] = v;
                    max[x] = v;
                } else if (v < min[x]) {
                    min[x] = v;
                } else if (v > max[x]) {
                    max[x] = v;
                }
                last[x] = v;
                newest = t;
            }
        });
    }

    /** Widens {@code range} ({min, max}) to this series' visible values. */
    void widen(double[] range) {
        for (int x = 0; x < width; x++) {
            if (used[x]) {
                range[0] = Math.min(range[0], min[x]);
                range[1] = Math.max(range[1], max[x]);
            }
        }
    }

    /** The newest visible sample's time, {@link Long#MIN_VALUE} when none. */
    long newest() {
        return newest;
    }

    /**
     * Fills {@code xs}/{@code ys} (each at least {@code 4 * width + 2} long) with the polyline and answers
     * its number of points.
     */
    int polyline(int[] xs, int[] ys, int left, int top, int h, double[] range) {
        double scale = h / (range[1] - range[0]);
        double low = range[0];
        int bottom = top + h;
        int n = 0;
        if (hasBefore) {
            xs[n] = left;
            ys[n++] = bottom - (int) ((before - low) * scale);
        }
        for (int x = 0; x < width; x++) {
            if (!used[x]) {
                continue;
            }
            int px = left + x;
            int yFirst = bottom - (int) ((first[x] - low) * scale);
            int yLast = bottom - (int) ((last[x] - low) * scale);
            xs[n] = px;
            ys[n++] = yFirst;
            if (min[x] != max[x]) {
                int yMin = bottom - (int) ((min[x] - low) * scale);
                int yMax = bottom - (int) ((max[x] - low) * scale);
                // visit the extreme nearer to the first value first
                boolean minFirst = Math.abs(yMin - yFirst) <= Math.abs(yMax - yFirst);
                xs[n] = px;
                ys[n++] = minFirst ? yMin : yMax;
                xs[n] = px;
                ys[n++] = minFirst ? yMax : yMin;
            }
            if (yLast != ys[n - 1]) {
                xs[n] = px;
                ys[n++] = yLast;
            }
        }
        if (hasAfter) {
            xs[n] = left + width - 1;
            ys[n++] = bottom - (int) ((after - low) * scale);
        }
        return n;
    }
}
