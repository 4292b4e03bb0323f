package org.fdnet.runtime.library;

import org.fdnet.event.ValueType;
import org.fdnet.runtime.Data;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Value;

/**
 * A Data holding a vector of doubles: a posture (one value per joint or leg), a candidate posture.
 * Parameters: {@code initial} (numbers separated by commas or spaces; default: empty), {@code length}
 * (optional: values of another length are refused — a posture always has as many joints as the robot).
 */
public class DoublesData extends Data {
    private int length = -1;

    @Override
    public ValueType type() {
        return ValueType.DOUBLES;
    }

    @Override
    protected void init(NodeParameters parameters) {
        long l = parameters.longValue("length", -1);
        if (l == 0 || l < -1) {
            throw parameters.invalid("length", "must be a positive number of elements, was " + l);
        }
        length = (int) l;
        if (length > 0 && parameters.has("initial")) {
            int given = initialValue(parameters).length();
            if (given != length) {
                throw parameters.invalid("initial", "has " + given + " values but length is " + length);
            }
        }
    }

    @Override
    protected Value initialValue(NodeParameters parameters) {
        if (!parameters.has("initial") && length > 0) {
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
