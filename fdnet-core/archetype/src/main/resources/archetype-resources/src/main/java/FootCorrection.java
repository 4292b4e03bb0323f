package ${package};

import org.fdnet.event.ValueType;
import org.fdnet.runtime.Data;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Value;

/**
 * A correction to add to RoQ's feet: 12 numbers, x, y and z of each leg in the body frame, in metres. It is a safety
 * envelope as well as a value: a vector of another length, a NaN or an element beyond {@code bound} is refused, so
 * the Relation that wrote it fails (and the network runs on without its correction) instead of moving a foot too
 * far.
 *
 * <p>Parameter: {@code bound}, declared below.
 */
public class FootCorrection extends Data {
    public static final ParameterSpec<Double> BOUND = ParameterSpec.number("bound").unit("m").above(0).atMost(0.05)
            .defaultValue(0.02).describe("the largest correction of any coordinate");

    /** Four legs, x, y and z each. */
    public static final int LENGTH = 12;

    private double bound;

    @Override
    public ValueType type() {
        return ValueType.DOUBLES;
    }

    @Override
    protected void init(NodeParameters parameters) {
        bound = BOUND.read(parameters);
    }

    /** No correction until a Relation writes one. */
    @Override
    protected Value initialValue(NodeParameters parameters) {
        return Value.ofDoubles(new double[LENGTH]);
    }

    @Override
    protected Value accept(Value proposed) {
        if (proposed.length() != LENGTH) {
            throw new IllegalArgumentException("a correction has " + LENGTH + " numbers (x, y, z of 4 feet), not "
                    + proposed.length());
        }
        for (int i = 0; i < LENGTH; i++) {
            double metres = proposed.element(i);
            if (!(Math.abs(metres) <= bound)) {
                throw new IllegalArgumentException("element " + i + " is " + metres + " m, beyond the bound of "
                        + bound + " m");
            }
        }
        return proposed;
    }
}
