package org.fdnet.runtime.library;

import org.fdnet.event.ValueType;
import org.fdnet.runtime.Data;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Value;

/**
 * A Data holding a number. Parameters: {@code initial} (default 0), {@code min} and {@code max}
 * (optional: values written outside are clamped, so a wild Relation cannot command an impossible value).
 */
public class DoubleData extends Data {
    private double min = Double.NEGATIVE_INFINITY;
    private double max = Double.POSITIVE_INFINITY;

    @Override
    public ValueType type() {
        return ValueType.DOUBLE;
    }

    @Override
    protected void init(NodeParameters parameters) {
        min = parameters.doubleValue("min", min);
        max = parameters.doubleValue("max", max);
        if (min > max) {
            throw parameters.invalid("min", "(" + min + ") is above max (" + max + ")");
        }
    }

    @Override
    protected Value accept(Value proposed) {
        double d = proposed.asDouble();
        if (Double.isNaN(d)) {
            throw new IllegalArgumentException("NaN is not a value");
        }
        return d < min ? Value.of(min) : d > max ? Value.of(max) : proposed;
    }
}
