package org.fdnet.event.wire;

import java.nio.charset.StandardCharsets;

/**
 * Reads a logged value's text as a number straight from the frame's bytes, with exactly the results of
 * {@link Double#parseDouble} and {@link Long#parseLong} on the trimmed text, without making a String when it
 * can. The fast path takes plain decimals ({@code -12.5}, {@code 3e-7}) whose digits, read as an integer, are
 * below 2^53 and whose power of ten lies in 10^-22..10^22: both are exact doubles, so one multiplication or
 * division is correctly rounded (Clinger's fast path) and the answer is the JDK's. Anything else (17
 * significant digits, {@code NaN}, hex, a suffix, non-ASCII digits) goes through a String to the JDK's parser.
 */
final class AsciiNumber {
    private static final long EXACT_MANTISSA = 1L << 53;
    private static final double[] POWERS = new double[23];

    static {
        double p = 1;
        for (int i = 0; i < POWERS.length; i++) {
            POWERS[i] = p;
            p *= 10;
        }
    }

    private AsciiNumber() {
    }

    /** The double of {@code b[from, to)}; throws {@link NumberFormatException} as the JDK does. */
    static double parseDouble(byte[] b, int from, int to) {
        int start = trimStart(b, from, to);
        int end = trimEnd(b, start, to);
        double fast = fastDouble(b, start, end);
        if (!Double.isNaN(fast)) {
            return fast;
        }
        return Double.parseDouble(new String(b, start, end - start, StandardCharsets.UTF_8));
    }

    /** The long of {@code b[from, to)} as a double; throws {@link NumberFormatException} as the JDK does. */
    static double parseLong(byte[] b, int from, int to) {
        int start = trimStart(b, from, to);
        int end = trimEnd(b, start, to);
        int i = start;
        boolean negative = i < end && b[i] == '-';
        if (i < end && (b[i] == '-' || b[i] == '+')) {
            i++;
        }
        if (i < end && end - i <= 18) {
            long v = 0;
            for (; i < end; i++) {
                int d = b[i] - '0';
                if (d < 0 || d > 9) {
                    break;
                }
                v = v * 10 + d;
            }
            if (i == end) {
                return negative ? -v : v;
            }
        }
        return Long.parseLong(new String(b, start, end - start, StandardCharsets.UTF_8));
    }

    /** NaN when the fast path does not apply (the text is then not a plain decimal, or not exact). */
    private static double fastDouble(byte[] b, int i, int end) {
        boolean negative = false;
        if (i < end && (b[i] == '-' || b[i] == '+')) {
            negative = b[i] == '-';
            i++;
        }
        long mantissa = 0;
        int digits = 0;
        int significant = 0;
        int fractionDigits = 0;
        boolean point = false;
        for (; i < end; i++) {
            int c = b[i];
            if (c == '.' && !point) {
                point = true;
            } else if (c >= '0' && c <= '9') {
                digits++;
                if (point) {
                    fractionDigits++;
                }
                if (mantissa != 0 || c != '0') {
                    if (++significant > 18) {
                        return Double.NaN;
                    }
                }
                mantissa = mantissa * 10 + (c - '0');
            } else {
                break;
            }
        }
        if (digits == 0) {
            return Double.NaN;
        }
        int exponent = 0;
        if (i < end && (b[i] == 'e' || b[i] == 'E')) {
            i++;
            boolean negativeExponent = false;
            if (i < end && (b[i] == '-' || b[i] == '+')) {
                negativeExponent = b[i] == '-';
                i++;
            }
            int expDigits = 0;
            for (; i < end && b[i] >= '0' && b[i] <= '9'; i++) {
                if (++expDigits > 4) {
                    return Double.NaN;
                }
                exponent = exponent * 10 + (b[i] - '0');
            }
            if (expDigits == 0) {
                return Double.NaN;
            }
            exponent = negativeExponent ? -exponent : exponent;
        }
        if (i != end || mantissa >= EXACT_MANTISSA) {
            return Double.NaN;
        }
        int power = exponent - fractionDigits;
        double value;
        if (mantissa == 0) {
            value = 0;
        } else if (power >= 0 && power < POWERS.length) {
            value = mantissa * POWERS[power];
        } else if (power < 0 && -power < POWERS.length) {
            value = mantissa / POWERS[-power];
        } else {
            return Double.NaN;
        }
        return negative ? -value : value;
    }

    private static int trimStart(byte[] b, int i, int end) {
        while (i < end && (b[i] & 0xFF) <= ' ') {
            i++;
        }
        return i;
    }

    private static int trimEnd(byte[] b, int start, int end) {
        while (end > start && (b[end - 1] & 0xFF) <= ' ') {
            end--;
        }
        return end;
    }
}
