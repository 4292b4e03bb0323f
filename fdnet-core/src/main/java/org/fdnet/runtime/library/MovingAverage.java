package org.fdnet.runtime.library;

import java.util.ArrayDeque;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * The mean of the last {@code window} (default 10) values of its first input, written to all outputs;
 * vectors are averaged element by element (a change of length starts the window again).
 */
public class MovingAverage extends Relation {
    public static final ParameterSpec<Long> WINDOW = ParameterSpec.whole("window").unit("values").atLeast(1)
            .defaultValue(10L).describe("how many of the latest values are averaged").live();

    private int window;
    private final ArrayDeque<double[]> values = new ArrayDeque<>();
    private double[] sum;

    @Override
    protected void init(NodeParameters p) {
        window = WINDOW.read(p).intValue();
    }

    @Override
    protected void compute(RelationContext context) {
        if (context.inputCount() == 0 || !context.inputChanged(0)) {
            return;
        }
        Value in = context.input(0);
        double[] x = in.asDoubles();
        if (sum == null || sum.length != x.length) {
            values.clear();
            sum = new double[x.length];
        }
        values.addLast(x);
        for (int i = 0; i < x.length; i++) {
            sum[i] += x[i];
        }
        if (values.size() > window) {
            double[] old = values.removeFirst();
            for (int i = 0; i < x.length; i++) {
                sum[i] -= old[i];
            }
        }
        double[] mean = new double[x.length];
        for (int i = 0; i < x.length; i++) {
            mean[i] = sum[i] / values.size();
        }
        context.outputAll(in.length() == 1 && in.isScalar() ? Value.of(mean[0]) : Value.ofDoubles(mean));
    }
}
