package org.fdnet.runtime.library;

import org.fdnet.event.ValueType;
import org.fdnet.runtime.Data;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Value;

/**
 * A Data holding a number. Parameters: {@code initial} (default 0), {@code min} and {@code max}
 * (optional: values written outside are clamped, so a wild Relation cannot command an impossible value).
 */
public class DoubleData extends Data {
    public static final ParameterSpec<Double> MIN = ParameterSpec.number("min").defaultDescribed("none")
            .describe("values written below it are raised to it").live();
    public static final ParameterSpec<Double> MAX = ParameterSpec.number("max").defaultDescribed("none")
            .describe("values written above it are lowered to it").live();

    private double min = Double.NEGATIVE_INFINITY;
    private double max = Double.POSITIVE_INFINITY;

    @Override
    public ValueType type() {
        return ValueType.DOUBLE;
    }

    @Override
    protected void init(NodeParameters parameters) {
        min = MIN.readOr(parameters, min);
        max = MAX.readOr(parameters, max);
        if (min > max) {
            throw parameters.conflict(MIN, MAX, "min must not be above max");
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
