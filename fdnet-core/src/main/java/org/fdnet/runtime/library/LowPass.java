package org.fdnet.runtime.library;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * A first-order low-pass filter of its first input: {@code y += a (x - y)}. Give either {@code alpha}
 * (0 &lt; a ≤ 1, the same every firing) or {@code cutoff} in Hz (a computed from the time between the
 * input's values, so the filter is right whatever the rate). Vectors are filtered element by element.
 */
public class LowPass extends Relation {
    private double alpha = Double.NaN;
    private double timeConstant = Double.NaN;
    private double[] y;
    private long lastTime;

    @Override
    protected void init(NodeParameters p) {
        if (p.has("alpha") == p.has("cutoff")) {
            throw p.invalid("alpha", "or 'cutoff' (Hz) is required, and only one of them");
        }
        if (p.has("alpha")) {
            alpha = p.requireDouble("alpha");
            if (!(alpha > 0 && alpha <= 1)) {
                throw p.invalid("alpha", "must be in (0, 1], was " + alpha);
            }
        } else {
            double cutoff = p.requireDouble("cutoff");
            if (!(cutoff > 0)) {
                throw p.invalid("cutoff", "must be above 0 Hz, was " + cutoff);
            }
            timeConstant = 1.0 / (2 * Math.PI * cutoff);
        }
    }

    @Override
    protected void compute(RelationContext context) {
        if (context.inputCount() == 0 || !context.inputChanged(0)) {
            return;
        }
        Value in = context.input(0);
        double[] x = in.asDoubles();
        if (y == null || y.length != x.length) {
            y = x.clone();
        } else {
            double a = alpha;
            if (Double.isNaN(a)) {
                double dt = Math.max(0, in.time() - lastTime) / 1e6;
                a = dt / (timeConstant + dt);
            }
            for (int i = 0; i < x.length; i++) {
                y[i] += a * (x[i] - y[i]);
            }
        }
        lastTime = in.time();
        context.outputAll(in.isScalar() ? Value.of(y[0]) : Value.ofDoubles(y));
    }
}
