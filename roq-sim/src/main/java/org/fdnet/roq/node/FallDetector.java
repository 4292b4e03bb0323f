package org.fdnet.roq.node;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Fall detection: reads the attitude (roll, pitch; rad) and writes {@code true} to its outputs once either
 * exceeds {@code limit} (default 0.6 rad), and keeps it (a fallen robot stays fallen until the network restarts);
 * {@code false} until then. Reports "fallen at t s".
 */
public class FallDetector extends Relation {
    private double limit;
    private boolean fallen;

    public static final ParameterSpec<Double> LIMIT = ParameterSpec.number("limit").unit("rad").above(0).below(Math.PI)
            .defaultValue(0.6).describe("the roll or pitch beyond which RoQ has fallen").live();

    @Override
    protected void init(NodeParameters p) {
        limit = LIMIT.read(p);
    }

    @Override
    protected void compute(RelationContext c) {
        Value attitude = c.input(0);
        if (attitude == null || attitude.length() < 2) {
            return;
        }
        if (!fallen && (Math.abs(attitude.element(0)) > limit || Math.abs(attitude.element(1)) > limit)) {
            fallen = true;
            c.report(String.format(java.util.Locale.ROOT, "fallen at %.3f s", c.seconds()));
        }
        c.outputAll(Value.of(fallen));
    }
}
