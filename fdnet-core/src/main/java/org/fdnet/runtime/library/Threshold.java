package org.fdnet.runtime.library;

import org.fdnet.runtime.NodeParameters;
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
    private double high;
    private double low;
    private boolean absolute;
    private Boolean state;

    @Override
    protected void init(NodeParameters p) {
        high = p.requireDouble("high");
        low = p.doubleValue("low", high);
        absolute = p.booleanValue("absolute", false);
        if (low > high) {
            throw p.invalid("low", "(" + low + ") is above high (" + high + ")");
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
