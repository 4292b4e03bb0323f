package org.fdnet.netinfo;

/**
 * The numbers a setting accepts: a lower and an upper bound, each included or not, either of them open-ended
 * (an infinite bound). Node parameters ({@code org.fdnet.runtime.ParameterSpec}) and the logger's settings both check
 * with it, so a refusal is worded alike everywhere and always names what is allowed:
 * {@code "writer.batchSize must be in [1, 1000000], was 0"}, {@code "must be above 0 N, was -2"}.
 *
 * @param min          the lower bound ({@link Double#NEGATIVE_INFINITY}: none)
 * @param minIncluded  whether {@code min} itself is allowed
 * @param max          the upper bound ({@link Double#POSITIVE_INFINITY}: none)
 * @param maxIncluded  whether {@code max} itself is allowed
 */
public record ValueRange(double min, boolean minIncluded, double max, boolean maxIncluded) {
    /** Every number but NaN. */
    public static final ValueRange ANY = new ValueRange(Double.NEGATIVE_INFINITY, false, Double.POSITIVE_INFINITY, false);

    /**
     * Checks that the bounds make a range.
     *
     * @param min         the lower bound ({@link Double#NEGATIVE_INFINITY}: none)
     * @param minIncluded whether {@code min} itself is allowed
     * @param max         the upper bound ({@link Double#POSITIVE_INFINITY}: none)
     * @param maxIncluded whether {@code max} itself is allowed
     * @throws IllegalArgumentException when a bound is NaN or the lower one lies above the upper one
     */
    public ValueRange {
        if (Double.isNaN(min) || Double.isNaN(max) || min > max) {
            throw new IllegalArgumentException("no numbers lie between " + format(min) + " and " + format(max));
        }
    }

    /**
     * From {@code min} to {@code max}, both included.
     *
     * @param min the smallest number allowed
     * @param max the largest number allowed
     * @return the range {@code [min, max]}
     */
    public static ValueRange closed(double min, double max) {
        return new ValueRange(min, true, max, true);
    }

    /**
     * The same range with another lower bound.
     *
     * @param bound    the new lower bound
     * @param included whether the bound itself is allowed
     * @return a new range
     */
    public ValueRange withMin(double bound, boolean included) {
        return new ValueRange(bound, included, max, maxIncluded);
    }

    /**
     * The same range with another upper bound.
     *
     * @param bound    the new upper bound
     * @param included whether the bound itself is allowed
     * @return a new range
     */
    public ValueRange withMax(double bound, boolean included) {
        return new ValueRange(min, minIncluded, bound, included);
    }

    /**
     * Whether {@code value} lies in this range (NaN never does).
     *
     * @param value the number to check
     * @return true when it is allowed
     */
    public boolean contains(double value) {
        boolean aboveMin = minIncluded ? value >= min : value > min;
        boolean belowMax = maxIncluded ? value <= max : value < max;
        return aboveMin && belowMax;
    }

    /**
     * Whether the range has a bound at all.
     *
     * @return false for {@link #ANY}
     */
    public boolean isBounded() {
        return min != Double.NEGATIVE_INFINITY || max != Double.POSITIVE_INFINITY;
    }

    /**
     * The range in words, to follow "must be": {@code in [0, 0.3] m}, {@code at least 1}, {@code above 0 Hz},
     * {@code at most 5 s}, {@code below 1}.
     *
     * @param unit the unit written after the numbers ("" for none)
     * @return the phrase; {@code "any number"} for {@link #ANY}
     */
    public String phrase(String unit) {
        String u = unit == null || unit.isEmpty() ? "" : " " + unit;
        boolean hasMin = min != Double.NEGATIVE_INFINITY;
        boolean hasMax = max != Double.POSITIVE_INFINITY;
        if (hasMin && hasMax) {
            return "in " + (minIncluded ? "[" : "(") + format(min) + ", " + format(max) + (maxIncluded ? "]" : ")") + u;
        }
        if (hasMin) {
            return (minIncluded ? "at least " : "above ") + format(min) + u;
        }
        if (hasMax) {
            return (maxIncluded ? "at most " : "below ") + format(max) + u;
        }
        return "any number";
    }

    /**
     * Refuses a number outside the range with one message naming the setting, the range and the number.
     *
     * @param what  the setting, as the user spells it (e.g. {@code writer.batchSize})
     * @param value the number given
     * @param unit  the unit ("" for none)
     * @throws IllegalArgumentException {@code "WHAT must be PHRASE, was VALUE"} when it lies outside
     */
    public void check(String what, double value, String unit) {
        if (!contains(value)) {
            throw new IllegalArgumentException(what + " must be " + phrase(unit) + ", was " + format(value));
        }
    }

    /**
     * A number as a user would write it: {@code 3} rather than {@code 3.0}, {@code 0.3} as given.
     *
     * @param value the number
     * @return its shortest faithful text
     */
    public static String format(double value) {
        if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            return Long.toString((long) value);
        }
        return Double.toString(value);
    }
}
