package org.fdnet.roq.node;

/**
 * Half-planes a·x + b·y ≤ c on a point in the plane, each of a rank (0 the most binding), and the point nearest a
 * wanted one that lies in all of them ({@link #nearest}). When no point lies in all, the half-planes of the last
 * rank are given up, then of the one before, until some point fits. A small exact solver: the nearest point of a
 * convex polygon to one outside it is the projection onto an edge or a corner, so it tries those. It allocates
 * nothing after construction.
 */
final class PlanarConstraints {
    private static final double SLACK = 1e-9;
    private final double[] a;
    private final double[] b;
    private final double[] c;
    private final int[] rank;
    private int n;

    /** Room for at most {@code capacity} half-planes. */
    PlanarConstraints(int capacity) {
        a = new double[capacity];
        b = new double[capacity];
        c = new double[capacity];
        rank = new int[capacity];
    }

    /** Forgets every half-plane. */
    void clear() {
        n = 0;
    }

    /** Adds a·x + b·y ≤ c of rank {@code r}; a zero normal is ignored (it constrains nothing or everything). */
    void add(double na, double nb, double nc, int r) {
        double len = Math.hypot(na, nb);
        if (len < 1e-12) {
            return;
        }
        if (n == a.length) {
            throw new IllegalStateException("more than " + a.length + " half-planes");
        }
        a[n] = na / len;
        b[n] = nb / len;
        c[n] = nc / len;
        rank[n] = r;
        n++;
    }

    /** How many half-planes there are. */
    int size() {
        return n;
    }

    /**
     * Writes into {@code out} the point nearest ({@code wx}, {@code wy}) that lies in every half-plane of rank at most
     * the returned one (all ranks when it can); returns −1, {@code out} the wanted point, when even rank 0 has none.
     */
    int nearest(double wx, double wy, double[] out) {
        int top = 0;
        for (int i = 0; i < n; i++) {
            top = Math.max(top, rank[i]);
        }
        for (int r = top; r >= 0; r--) {
            if (nearest(wx, wy, r, out)) {
                return r;
            }
        }
        out[0] = wx;
        out[1] = wy;
        return -1;
    }

    /** Whether (x, y) lies in every half-plane of rank at most {@code r}, to within a nanometre. */
    boolean inside(double x, double y, int r) {
        for (int i = 0; i < n; i++) {
            if (rank[i] <= r && a[i] * x + b[i] * y > c[i] + SLACK) {
                return false;
            }
        }
        return true;
    }

    private boolean nearest(double wx, double wy, int r, double[] out) {
        if (inside(wx, wy, r)) {
            out[0] = wx;
            out[1] = wy;
            return true;
        }
        double best = Double.POSITIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            if (rank[i] > r) {
                continue;
            }
            // the projection onto line i
            double d = a[i] * wx + b[i] * wy - c[i];
            best = consider(wx - d * a[i], wy - d * b[i], wx, wy, r, best, out);
            for (int j = i + 1; j < n; j++) {
                if (rank[j] > r) {
                    continue;
                }
                double det = a[i] * b[j] - a[j] * b[i];
                if (Math.abs(det) < 1e-12) {
                    continue;
                }
                double x = (c[i] * b[j] - c[j] * b[i]) / det;
                double y = (a[i] * c[j] - a[j] * c[i]) / det;
                best = consider(x, y, wx, wy, r, best, out);
            }
        }
        return best < Double.POSITIVE_INFINITY;
    }

    private double consider(double x, double y, double wx, double wy, int r, double best, double[] out) {
        double d = Math.hypot(x - wx, y - wy);
        if (d < best && inside(x, y, r)) {
            out[0] = x;
            out[1] = y;
            return d;
        }
        return best;
    }
}
