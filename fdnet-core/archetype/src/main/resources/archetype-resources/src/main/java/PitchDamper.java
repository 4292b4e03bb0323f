package ${package};

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Damps RoQ's pitching with its legs: when the nose dips the front feet reach down and the hind feet draw up (in the
 * body frame), in proportion to the pitch the inclinometer measures, so the body is pushed back toward level.
 * Each foot's height moves by {@code -gain · x · pitch}, where x is how far ahead of the body's centre the gait puts
 * that foot, and by no more than {@code limit}.
 *
 * <p>Inputs (by name): {@code attitude} (roll, pitch in rad; pitch &gt; 0 is nose down) and {@code gait feet} (12,
 * the gait's feet in the body frame). Output 0: the correction to add to the feet (12 numbers; only z is non-zero).
 * Parameters: {@code gain} (default 0.5, between 0 and 2) and {@code limit} (m, default 0.01, between 0 and 0.03).
 */
public class PitchDamper extends Relation {
    private static final int LEGS = 4;

    private final double[] correction = new double[3 * LEGS];
    private double gain;
    private double limit;

    @Override
    protected void init(NodeParameters parameters) {
        gain = parameters.doubleValue("gain", 0.5);
        limit = parameters.doubleValue("limit", 0.01);
        if (!(gain >= 0) || gain > 2) {
            throw parameters.invalid("gain", "must lie between 0 and 2, was " + gain);
        }
        if (!(limit >= 0) || limit > 0.03) {
            throw parameters.invalid("limit", "must lie between 0 and 0.03 m, was " + limit);
        }
    }

    @Override
    protected void compute(RelationContext c) {
        Value attitude = c.input("attitude");
        Value feet = c.input("gait feet");
        if (attitude == null || attitude.length() < 2 || feet == null || feet.length() < 3 * LEGS) {
            c.report("waiting for " + c.missingInputs());
            return;
        }
        double pitch = attitude.element(1);
        for (int leg = 0; leg < LEGS; leg++) {
            double x = feet.element(3 * leg);
            correction[3 * leg + 2] = Math.max(-limit, Math.min(limit, -gain * x * pitch));
        }
        c.output(0, Value.ofDoubles(correction));
    }
}
