package org.acme.guard;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/** Raises an alarm while the body tilts more than {@code limit} rad in roll or pitch. Input: attitude. Output: alarm. */
public class TiltGuard extends Relation {
    private double limit;

    @Override
    protected void init(NodeParameters parameters) {
        limit = parameters.doubleValue("limit", 0.3);
        if (!(limit > 0) || limit > 1.5) {
            throw parameters.invalid("limit", "must lie in (0, 1.5] rad, was " + limit);
        }
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
