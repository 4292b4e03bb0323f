package org.fdnet.runtime.library;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * A switch with hysteresis on its first input: the output becomes {@code true} when the input rises above
 * {@code high} and {@code false} when it falls below {@code low} (required, low ≤ high); in between it
 * keeps its state, so a noisy signal near the threshold does not chatter. With {@code absolute = true}
 * the input's magnitude is compared. Writes on the first firing and whenever the state changes.
 */
public class Threshold extends Relation {
    public static final ParameterSpec<Double> HIGH = ParameterSpec.number("high")
            .describe("the output becomes true when the input rises above it").live();
    public static final ParameterSpec<Double> LOW = ParameterSpec.number("low").defaultDescribed("high")
            .describe("the output becomes false when the input falls below it").live();
    public static final ParameterSpec<Boolean> ABSOLUTE = ParameterSpec.flag("absolute").defaultValue(false)
            .describe("compare the input's magnitude").live();

    private double high;
    private double low;
    private boolean absolute;
    private Boolean state;

    @Override
    protected void init(NodeParameters p) {
        high = HIGH.read(p);
        low = LOW.readOr(p, high);
        absolute = ABSOLUTE.read(p);
        if (low > high) {
            throw p.conflict(LOW, HIGH, "low must not be above high");
        }
    }

    @Override
    protected void compute(RelationContext context) {
        Value in = context.inputCount() == 0 ? null : context.input(0);
        if (in == null) {
            return;
        }
        double x = absolute ? Math.abs(in.asDouble()) : in.asDouble();
        boolean next = state == null ? x > high : state ? x >= low : x > high;
        if (state == null || next != state) {
            state = next;
            context.outputAll(Value.of(next));
        }
    }
}
