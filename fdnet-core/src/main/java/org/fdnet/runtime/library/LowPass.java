package org.fdnet.runtime.library;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * A first-order low-pass filter of its first input: {@code y += a (x - y)}. Give either {@code alpha}
 * (0 &lt; a ≤ 1, the same every firing) or {@code cutoff} in Hz (a computed from the time between the
 * input's values, so the filter is right whatever the rate). Vectors are filtered element by element.
 */
public class LowPass extends Relation {
    public static final ParameterSpec<Double> ALPHA = ParameterSpec.number("alpha").above(0).atMost(1).optional()
            .describe("the share of the step toward the input taken every firing (or give cutoff)").live();
    public static final ParameterSpec<Double> CUTOFF = ParameterSpec.number("cutoff").unit("Hz").above(0).optional()
            .describe("the cut-off frequency, whatever the input's rate (or give alpha)").live();

    private double alpha = Double.NaN;
    private double timeConstant = Double.NaN;
    private double[] y;
    private long lastTime;

    @Override
    protected void init(NodeParameters p) {
        if (ALPHA.isGiven(p) == CUTOFF.isGiven(p)) {
            throw p.conflict(ALPHA, CUTOFF, "give exactly one of them");
        }
        if (ALPHA.isGiven(p)) {
            alpha = ALPHA.read(p);
        } else {
            timeConstant = 1.0 / (2 * Math.PI * CUTOFF.read(p));
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
