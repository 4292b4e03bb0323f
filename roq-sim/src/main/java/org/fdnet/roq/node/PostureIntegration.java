package org.fdnet.roq.node;

import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * The integration of Figure 5's candidate postures: the first input is the base posture (the gait's feet, 12
 * numbers), every further input a correction to add (the balance shift, a probe's lowering…). A correction whose
 * module is not loaded reads as missing and is left out: the posture integrates what is there.
 */
public class PostureIntegration extends Relation {
    @Override
    protected void compute(RelationContext c) {
        Value base = c.input(0);
        if (base == null) {
            c.report("no base posture");
            return;
        }
        double[] sum = base.asDoubles().clone();
        int used = 0;
        for (int i = 1; i < c.inputCount(); i++) {
            Value v = c.input(i);
            if (v != null && v.length() == sum.length) {
                for (int k = 0; k < sum.length; k++) {
                    sum[k] += v.element(k);
                }
                used++;
            }
        }
        c.report(used + " of " + (c.inputCount() - 1) + " corrections");
        c.outputAll(Value.ofDoubles(sum));
    }
}
