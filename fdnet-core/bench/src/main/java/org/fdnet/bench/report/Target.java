package org.fdnet.bench.report;

/**
 * What a figure must reach: a bound on the figure itself or on its ratio to the same-run baseline.
 *
 * @param onRatio whether the bound applies to figure / baseline rather than to the figure
 * @param atMost  whether the figure (or ratio) must stay at or below the bound, else reach at least it
 * @param bound   the bound, in the figure's unit (or a plain ratio)
 */
record Target(boolean onRatio, boolean atMost, double bound) {
    static Target atMost(double bound) {
        return new Target(false, true, bound);
    }

    static Target atLeast(double bound) {
        return new Target(false, false, bound);
    }

    static Target ratioAtMost(double bound) {
        return new Target(true, true, bound);
    }

    static Target ratioAtLeast(double bound) {
        return new Target(true, false, bound);
    }

    /** Whether it holds; a ratio target without a baseline (NaN) does not. */
    boolean met(double figure, double ratio) {
        double x = onRatio ? ratio : figure;
        if (Double.isNaN(x)) {
            return false;
        }
        return atMost ? x <= bound : x >= bound;
    }

    /** As the table shows it, e.g. {@code ≤ 2 µs} or {@code ≥ 0.9× baseline}. */
    String text(String unit) {
        String sign = atMost ? "≤ " : "≥ ";
        String number = Figures.format(bound);
        if (number.contains(".")) {
            number = number.replaceAll("0+$", "").replaceAll("\\.$", ""); // a bound is exact: 0.9, not 0.900
        }
        return onRatio ? sign + number + "× baseline" : sign + number + " " + unit;
    }
}
