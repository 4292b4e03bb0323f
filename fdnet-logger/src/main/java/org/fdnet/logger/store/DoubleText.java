package org.fdnet.logger.store;

/**
 * A double as the decimal text COPY stores, written into a byte array without making a String: the value
 * column is text (the thesis's schema), and since protocol version 2 the logger receives numbers in binary,
 * so this is where a number becomes text — once, outside any core's lock.
 *
 * <p>The fast path covers the plain notation {@code Double.toString} uses (|v| in [10^-3, 10^7)): it finds the
 * fewest fraction digits {@code k} for which {@code m / 10^k}, computed in double arithmetic (correctly
 * rounded, {@code m} and {@code 10^k} exact), is {@code v} itself — so parsing the text gives back exactly
 * {@code v}, and the text is the shortest such in plain notation (e.g. {@code 0.25}, {@code 1234.567},
 * {@code 3.0}). Anything else (large, tiny, NaN, infinite, or needing more digits) goes through
 * {@code Double.toString}.
 */
final class DoubleText {
    /** Exact powers of ten up to 10^17 (every one below 2^53 · 10 is a double exactly). */
    private static final double[] POW10 = new double[18];
    private static final long[] LONG_POW10 = new long[18];
    /** m must stay below 2^53 so that it and the division are exact. */
    private static final double MAX_EXACT = 9007199254740992.0;

    static {
        long p = 1;
        for (int i = 0; i < POW10.length; i++) {
            LONG_POW10[i] = p;
            POW10[i] = p;
            p *= 10;
        }
    }

    private DoubleText() {
    }

    /**
     * Writes {@code v} at {@code at} in {@code buf} (room for 32 bytes is the caller's) and answers the end.
     */
    static int write(double v, byte[] buf, int at) {
        double abs = Math.abs(v);
        if (abs >= 1e-3 && abs < 1e7) {
            for (int k = 1; k < POW10.length; k++) {
                double scaled = abs * POW10[k];
                if (scaled >= MAX_EXACT) {
                    break;
                }
                long m = Math.round(scaled);
                if (m / POW10[k] == abs) {
                    return plain(v < 0, m, k, buf, at);
                }
            }
        }
        String text = Double.toString(v);
        for (int i = 0; i < text.length(); i++) {
            buf[at++] = (byte) text.charAt(i);
        }
        return at;
    }

    /** {@code m / 10^k} as {@code [-]int.frac}, with k ≥ 1 fraction digits; a trailing zero trimmed but one kept. */
    private static int plain(boolean negative, long m, int k, byte[] buf, int at) {
        if (negative) {
            buf[at++] = '-';
        }
        long whole = m / LONG_POW10[k];
        long fraction = m % LONG_POW10[k];
        at = digits(whole, buf, at);
        buf[at++] = '.';
        for (int i = k - 1; i >= 0; i--) { // leading zeros of the fraction included
            long d = fraction / LONG_POW10[i];
            buf[at++] = (byte) ('0' + d);
            fraction -= d * LONG_POW10[i];
        }
        return at;
    }

    private static int digits(long v, byte[] buf, int at) {
        int n = 1;
        while (n < LONG_POW10.length && v >= LONG_POW10[n]) { // v < 10^7 here
            n++;
        }
        for (int i = at + n - 1; i >= at; i--) {
            buf[i] = (byte) ('0' + v % 10);
            v /= 10;
        }
        return at + n;
    }
}
