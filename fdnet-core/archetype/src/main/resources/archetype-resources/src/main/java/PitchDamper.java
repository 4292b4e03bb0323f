package ${package};

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
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
 * Its parameters are declared below: the engine checks them before {@code init}, {@code fdnet info --params} and the
 * editor list them, and a running network changes only those declared {@code live()}.
 */
public class PitchDamper extends Relation {
    public static final ParameterSpec<Double> GAIN = ParameterSpec.number("gain").unit("m/(m rad)").range(0, 2)
            .defaultValue(0.5).describe("how much a foot moves per metre ahead of the centre and radian of pitch").live();
    public static final ParameterSpec<Double> LIMIT = ParameterSpec.number("limit").unit("m").range(0, 0.03)
            .defaultValue(0.01).describe("the most any foot's height moves").live();

    private static final int LEGS = 4;

    private final double[] correction = new double[3 * LEGS];
    private double gain;
    private double limit;

    @Override
    protected void init(NodeParameters parameters) {
        gain = GAIN.read(parameters);
        limit = LIMIT.read(parameters);
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
