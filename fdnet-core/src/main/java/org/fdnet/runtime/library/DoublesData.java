package org.fdnet.runtime.library;

import org.fdnet.event.ValueType;
import org.fdnet.runtime.Data;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Value;

/**
 * A Data holding a vector of doubles: a posture (one value per joint or leg), a candidate posture.
 * Parameters: {@code initial} (numbers separated by commas or spaces; default: empty), {@code length}
 * (optional: values of another length are refused — a posture always has as many joints as the robot).
 */
public class DoublesData extends Data {
    public static final ParameterSpec<Long> LENGTH = ParameterSpec.whole("length").atLeast(1)
            .defaultDescribed("any length").describe("the number of elements every value must have");

    private int length = -1;

    @Override
    public ValueType type() {
        return ValueType.DOUBLES;
    }

    @Override
    protected void init(NodeParameters parameters) {
        length = LENGTH.readOr(parameters, -1L).intValue();
        if (length > 0 && INITIAL.isGiven(parameters) && initialValue(parameters).length() != length) {
            throw parameters.conflict(INITIAL, LENGTH, "initial must have length values");
        }
    }

    @Override
    protected Value initialValue(NodeParameters parameters) {
        if (!INITIAL.isGiven(parameters) && length > 0) {
            return Value.ofDoubles(new double[length]);
        }
        return super.initialValue(parameters);
    }

    @Override
    protected Value accept(Value proposed) {
        if (length > 0 && proposed.length() != length) {
            throw new IllegalArgumentException("a vector of " + proposed.length() + " values where " + length + " are expected");
        }
        for (int i = 0; i < proposed.length(); i++) {
            if (Double.isNaN(proposed.element(i))) {
                throw new IllegalArgumentException("NaN at element " + i);
            }
        }
        return proposed;
    }
}
