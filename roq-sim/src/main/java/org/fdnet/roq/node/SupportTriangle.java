package org.fdnet.roq.node;

/** The support polygon of the feet on the ground, seen from above: three feet (a triangle) or four. */
final class SupportTriangle {
    private SupportTriangle() {
    }

    /** Distance of (x, y) to the nearest edge of the triangle (px, py), positive inside, negative outside. */
    static double margin(double[] px, double[] py, double x, double y) {
        return margin(px, py, 3, x, y);
    }

    /**
     * Distance of (x, y) to the nearest edge of the convex polygon of the first {@code n} corners (px, py), given
     * in order around it (either way round), positive inside, negative outside.
     */
    static double margin(double[] px, double[] py, int n, double x, double y) {
        double area = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            area += px[i] * py[j] - px[j] * py[i];
        }
        double sign = Math.signum(area);
        double m = Double.MAX_VALUE;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ex = px[j] - px[i];
            double ey = py[j] - py[i];
            double len = Math.hypot(ex, ey);
            double d = sign * (ex * (y - py[i]) - ey * (x - px[i])) / len;
            m = Math.min(m, d);
        }
        return m;
    }
}
