package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

/**
 * The contact-force distribution: how the weight {@code W}, coming down at the centre of pressure (cx, cy), is shared
 * by the feet on the ground. Vertical sole forces f only — no foot is asked for a force along the ground, so each
 * stays within its friction cone whatever the friction — satisfying the statics Σf = W, Σf·x = W·cx, Σf·y = W·cy:
 *
 * <ul>
 *   <li>three feet: the one solution, W times the barycentric coordinates of the centre of pressure;</li>
 *   <li>four feet: one free mode remains, the twist {@link #twist} along which the diagonal pairs trade load; the
 *   solution nearest the even share W/4 (least squares) is taken;</li>
 *   <li>a leg being unloaded before its lift, or loaded after its touchdown, by the share {@code s}: the mix
 *   (1 − s)·four-foot + s·three-foot-without-it — the two differ only along the twist, so the mix keeps the
 *   statics at every s;</li>
 *   <li>every foot on the ground is then given at least the minimum load (the leg being unloaded excepted).</li>
 * </ul>
 *
 * Allocation-free after construction; one instance per Relation.
 */
final class ForceDistribution {
    private final double[] three = new double[LEGS];
    private final double[] four = new double[LEGS];
    private final double[] twist = new double[LEGS];
    private final double[] lambda = new double[3];
    private boolean hasTwist;

    /**
     * The desired sole forces into {@code out} (N; −1 for a foot not on the ground): {@code x, y} each foot's position
     * (level frame), {@code down} which feet are on the ground, (cx, cy) the centre of pressure, {@code weight} N,
     * {@code least} the minimum load, {@code unloading} the leg whose share is being moved (−1: none) and
     * {@code unloaded} how much of it, 0..1.
     */
    void distribute(double[] x, double[] y, boolean[] down, double cx, double cy, double weight, double least,
                    int unloading, double unloaded, double[] out) {
        int n = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            n += down[leg] ? 1 : 0;
        }
        hasTwist = false;
        if (n == 4) {
            evenest(x, y, cx, cy, weight, four);
            hasTwist = twistMode(x, y, twist);
            if (unloading >= 0 && unloaded > 0 && barycentric(x, y, down, unloading, cx, cy, weight, three)) {
                for (int leg = 0; leg < LEGS; leg++) {
                    out[leg] = (1 - unloaded) * four[leg] + unloaded * three[leg];
                }
            } else {
                System.arraycopy(four, 0, out, 0, LEGS);
            }
        } else if (n == 3) {
            barycentric(x, y, down, -1, cx, cy, weight, out);
        } else {
            for (int leg = 0; leg < LEGS; leg++) {
                out[leg] = n == 0 ? 0 : weight / n;
            }
        }
        for (int leg = 0; leg < LEGS; leg++) {
            if (!down[leg]) {
                out[leg] = -1;
            } else if (leg != unloading || unloaded <= 0) {
                out[leg] = Math.max(least, out[leg]);
            } else {
                out[leg] = Math.max(0, out[leg]);
            }
        }
    }

    /** The twist of the last four-foot distribution (unit length), or null when there was none. */
    double[] twist() {
        return hasTwist ? twist : null;
    }

    /** Four feet: Σf = W and the moments, nearest to W/4 each (f = W/4 + Aᵀ(AAᵀ)⁻¹(b − A·W/4)). */
    private void evenest(double[] x, double[] y, double cx, double cy, double weight, double[] out) {
        double q = weight / LEGS;
        double sx = 0;
        double sy = 0;
        double sxx = 0;
        double syy = 0;
        double sxy = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            sx += x[leg];
            sy += y[leg];
            sxx += x[leg] * x[leg];
            syy += y[leg] * y[leg];
            sxy += x[leg] * y[leg];
        }
        // residual b − A·q1
        double r0 = 0;
        double r1 = weight * cx - q * sx;
        double r2 = weight * cy - q * sy;
        // AAᵀ = [[4, sx, sy], [sx, sxx, sxy], [sy, sxy, syy]]
        boolean solved = solve3(LEGS, sx, sy, sxx, sxy, syy, r0, r1, r2, lambda);
        for (int leg = 0; leg < LEGS; leg++) {
            out[leg] = q + (solved ? lambda[0] + lambda[1] * x[leg] + lambda[2] * y[leg] : 0);
        }
    }

    /** The null vector of A = [1; x; y] for four feet, unit length; false when the feet are degenerate. */
    static boolean twistMode(double[] x, double[] y, double[] out) {
        double norm = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            int a = (leg + 1) % LEGS;
            int b = (leg + 2) % LEGS;
            int c = (leg + 3) % LEGS;
            // cofactor: the determinant of the three other columns, with the alternating sign
            double det = (x[b] - x[a]) * (y[c] - y[a]) - (x[c] - x[a]) * (y[b] - y[a]);
            out[leg] = (leg % 2 == 0 ? 1 : -1) * det;
            norm += out[leg] * out[leg];
        }
        norm = Math.sqrt(norm);
        if (norm < 1e-9) {
            return false;
        }
        for (int leg = 0; leg < LEGS; leg++) {
            out[leg] /= norm;
        }
        return true;
    }

    /**
     * The three feet on the ground other than {@code without} (or the three {@code down}, when −1) carry W at their
     * barycentric coordinates of (cx, cy); the fourth gets 0. False when the triangle is degenerate.
     */
    private static boolean barycentric(double[] x, double[] y, boolean[] down, int without, double cx, double cy,
                                       double weight, double[] out) {
        int a = -1;
        int b = -1;
        int c = -1;
        for (int leg = 0; leg < LEGS; leg++) {
            out[leg] = 0;
            if (!down[leg] || leg == without) {
                continue;
            }
            if (a < 0) {
                a = leg;
            } else if (b < 0) {
                b = leg;
            } else if (c < 0) {
                c = leg;
            }
        }
        if (c < 0) {
            return false;
        }
        double det = (x[b] - x[a]) * (y[c] - y[a]) - (x[c] - x[a]) * (y[b] - y[a]);
        if (Math.abs(det) < 1e-9) {
            return false;
        }
        double lb = ((cx - x[a]) * (y[c] - y[a]) - (x[c] - x[a]) * (cy - y[a])) / det;
        double lc = ((x[b] - x[a]) * (cy - y[a]) - (cx - x[a]) * (y[b] - y[a])) / det;
        out[a] = weight * (1 - lb - lc);
        out[b] = weight * lb;
        out[c] = weight * lc;
        return true;
    }

    /** Solves the symmetric 3×3 system [[a, b, c], [b, d, e], [c, e, f]]·l = r into {@code l}; false if singular. */
    private static boolean solve3(double a, double b, double c, double d, double e, double f, double r0, double r1,
                                  double r2, double[] l) {
        double det = a * (d * f - e * e) - b * (b * f - e * c) + c * (b * e - d * c);
        if (Math.abs(det) < 1e-12) {
            return false;
        }
        double l0 = r0 * (d * f - e * e) - b * (r1 * f - e * r2) + c * (r1 * e - d * r2);
        double l1 = a * (r1 * f - e * r2) - r0 * (b * f - e * c) + c * (b * r2 - r1 * c);
        double l2 = a * (d * r2 - r1 * e) - b * (b * r2 - r1 * c) + r0 * (b * e - d * c);
        l[0] = l0 / det;
        l[1] = l1 / det;
        l[2] = l2 / det;
        return true;
    }
}
