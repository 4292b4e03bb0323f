package org.acme.guard;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/** Raises an alarm while the body tilts more than {@code limit} rad in roll or pitch. Input: attitude. Output: alarm. */
public class TiltGuard extends Relation {
    public static final ParameterSpec<Double> LIMIT = ParameterSpec.number("limit").unit("rad").above(0).atMost(1.5)
            .defaultValue(0.3).describe("the roll or pitch beyond which the alarm is raised").live();

    private double limit;

    @Override
    protected void init(NodeParameters parameters) {
        limit = LIMIT.read(parameters);
    }

    @Override
    protected void compute(RelationContext c) {
        Value attitude = c.input("attitude");
        if (attitude == null || attitude.length() < 2) {      // no reading yet
            c.report("waiting for " + c.missingInputs());
            return;
        }
        boolean tilted = Math.abs(attitude.element(0)) > limit || Math.abs(attitude.element(1)) > limit;
        c.output("alarm", Value.of(tilted));
    }
}
