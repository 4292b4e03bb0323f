package org.fdnet.runtime.library;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Follows its first input at no more than {@code maxRate} units per second (required, above 0): each
 * firing the output moves toward the input by at most {@code maxRate * dt}, dt being the time since the
 * previous firing. Vectors are limited element by element. Give it a {@code period} to keep moving
 * toward a target that no longer changes.
 */
public class RateLimiter extends Relation {
    public static final ParameterSpec<Double> MAX_RATE = ParameterSpec.number("maxRate").unit("units/s").above(0)
            .describe("the fastest the output follows the input").live();

    private double maxRate;
    private double[] out;
    private long lastMicros;

    @Override
    protected void init(NodeParameters p) {
        maxRate = MAX_RATE.read(p);
    }

    @Override
    protected void compute(RelationContext context) {
        Value in = context.inputCount() == 0 ? null : context.input(0);
        if (in == null) {
            return;
        }
        double[] target = in.asDoubles();
        long now = context.now();
        if (out == null || out.length != target.length) {
            out = target.clone();
        } else {
            double step = maxRate * Math.max(0, now - lastMicros) / 1e6;
            boolean moved = false;
            for (int i = 0; i < out.length; i++) {
                double next = out[i] + Math.max(-step, Math.min(step, target[i] - out[i]));
                moved |= next != out[i];
                out[i] = next;
            }
            if (!moved && !context.inputChanged(0)) {
                lastMicros = now;
                return;
            }
        }
        lastMicros = now;
        context.outputAll(in.isScalar() ? Value.of(out[0]) : Value.ofDoubles(out));
    }
}
