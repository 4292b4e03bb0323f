package org.fdnet.roq.node;

/** The support triangle of three feet on the ground, seen from above. */
final class SupportTriangle {
    private SupportTriangle() {
    }

    /** Distance of (x, y) to the nearest edge of the triangle (px, py), positive inside, negative outside. */
    static double margin(double[] px, double[] py, double x, double y) {
        double area = (px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0]);
        double sign = Math.signum(area);
        double m = Double.MAX_VALUE;
        for (int i = 0; i < 3; i++) {
            int j = (i + 1) % 3;
            double ex = px[j] - px[i];
            double ey = py[j] - py[i];
            double len = Math.hypot(ex, ey);
            double d = sign * (ex * (y - py[i]) - ey * (x - px[i])) / len;
            m = Math.min(m, d);
        }
        return m;
    }
}
