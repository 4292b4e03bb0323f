package org.fdnet.runtime.library;

import java.util.StringJoiner;
import java.util.function.DoubleUnaryOperator;

/** Element-by-element arithmetic on vectors of doubles; a vector of one spreads over any length. */
final class Vectors {
    private Vectors() {
    }

    @FunctionalInterface
    interface Op {
        double apply(double a, double b);
    }

    static int lengthOf(double[] a, double[] b) {
        if (a.length == b.length || b.length == 1) {
            return a.length;
        }
        if (a.length == 1) {
            return b.length;
        }
        throw new IllegalArgumentException("vectors of different lengths (" + a.length + " and " + b.length + ")");
    }

    static double[] combine(double[] a, double[] b, Op op) {
        int n = lengthOf(a, b);
        double[] r = new double[n];
        for (int i = 0; i < n; i++) {
            r[i] = op.apply(a[a.length == 1 ? 0 : i], b[b.length == 1 ? 0 : i]);
        }
        return r;
    }

    static double[] map(double[] a, DoubleUnaryOperator f) {
        double[] r = new double[a.length];
        for (int i = 0; i < a.length; i++) {
            r[i] = f.applyAsDouble(a[i]);
        }
        return r;
    }

    static double[] select(double[] c, double[] yes, double[] no) {
        int n = Math.max(c.length, Math.max(yes.length, no.length));
        for (double[] v : new double[][] {c, yes, no}) {
            if (v.length != 1 && v.length != n) {
                throw new IllegalArgumentException("vectors of different lengths (" + v.length + " and " + n + ")");
            }
        }
        double[] r = new double[n];
        for (int i = 0; i < n; i++) {
            double ci = c[c.length == 1 ? 0 : i];
            r[i] = ci != 0 ? yes[yes.length == 1 ? 0 : i] : no[no.length == 1 ? 0 : i];
        }
        return r;
    }

    static double[] concat(ExpressionParser.Node[] parts, ExpressionParser.Env env) {
        double[][] values = new double[parts.length][];
        int n = 0;
        for (int i = 0; i < parts.length; i++) {
            values[i] = parts[i].eval(env);
            n += values[i].length;
        }
        double[] r = new double[n];
        int at = 0;
        for (double[] v : values) {
            System.arraycopy(v, 0, r, at, v.length);
            at += v.length;
        }
        return r;
    }

    static String text(double[] v) {
        if (v.length == 1) {
            return Double.toString(v[0]);
        }
        StringJoiner j = new StringJoiner(", ", "[", "]");
        for (double d : v) {
            j.add(Double.toString(d));
        }
        return j.toString();
    }
}
