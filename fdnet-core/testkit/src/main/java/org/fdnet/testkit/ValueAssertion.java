package org.fdnet.testkit;

import java.time.Duration;
import java.util.Arrays;
import java.util.Locale;
import java.util.Objects;
import org.fdnet.event.ValueType;
import org.fdnet.runtime.Value;

/**
 * An assertion on one Data's value at one simulated instant, from {@link TestNetwork#assertValue}. Each check
 * returns the assertion so checks chain; a failure is an {@link AssertionError} naming the node, the simulated time,
 * the expectation and the value: {@code Lab/output at t = 0.020 s: expected 1.0 ± 1.0E-9, was 0.5 (DOUBLE)}.
 */
public final class ValueAssertion {
    private final String node;
    private final Value value;
    private final Duration time;

    ValueAssertion(String node, Value value, Duration time) {
        this.node = node;
        this.value = value;
        this.time = time;
    }

    /** @return this, after checking the Data has a value */
    public ValueAssertion isPresent() {
        if (value == null) {
            throw fail("a value");
        }
        return this;
    }

    /**
     * @param expected  the number expected
     * @param tolerance the largest difference accepted, ≥ 0
     * @return this, after checking the value is a number within {@code tolerance} of {@code expected}
     */
    public ValueAssertion isCloseTo(double expected, double tolerance) {
        if (value == null || !value.isScalar() || Math.abs(value.asDouble() - expected) > tolerance) {
            throw fail(expected + " ± " + tolerance);
        }
        return this;
    }

    /** @return this, after checking the value is a number above {@code bound} */
    public ValueAssertion isGreaterThan(double bound) {
        if (value == null || !value.isScalar() || !(value.asDouble() > bound)) {
            throw fail("more than " + bound);
        }
        return this;
    }

    /** @return this, after checking the value is a number below {@code bound} */
    public ValueAssertion isLessThan(double bound) {
        if (value == null || !value.isScalar() || !(value.asDouble() < bound)) {
            throw fail("less than " + bound);
        }
        return this;
    }

    /** @return this, after checking the value is the boolean true */
    public ValueAssertion isTrue() {
        if (value == null || value.type() != ValueType.BOOLEAN || !value.asBoolean()) {
            throw fail("true");
        }
        return this;
    }

    /** @return this, after checking the value is the boolean false */
    public ValueAssertion isFalse() {
        if (value == null || value.type() != ValueType.BOOLEAN || value.asBoolean()) {
            throw fail("false");
        }
        return this;
    }

    /**
     * @param expected a {@link Value} (compared by type and content), a {@code String} (compared with the value's
     *                 text), a {@code Number} (compared exactly as a double), a {@code Boolean} or a {@code double[]}
     * @return this, after checking the value equals {@code expected}
     */
    public ValueAssertion isEqualTo(Object expected) {
        if (value == null || !matches(expected)) {
            throw fail(expected instanceof double[] d ? Arrays.toString(d) : String.valueOf(expected));
        }
        return this;
    }

    private boolean matches(Object expected) {
        if (expected instanceof Value v) {
            return v.typed().equals(value.typed());
        } else if (expected instanceof String s) {
            return s.equals(value.text());
        } else if (expected instanceof Number n) {
            return value.isScalar() && value.asDouble() == n.doubleValue();
        } else if (expected instanceof Boolean b) {
            return value.type() == ValueType.BOOLEAN && value.asBoolean() == b;
        } else if (expected instanceof double[] d) {
            return value.type() == ValueType.DOUBLES && Arrays.equals(value.asDoubles(), d);
        }
        return Objects.equals(expected, value);
    }

    private AssertionError fail(String expected) {
        return new AssertionError(String.format(Locale.ROOT, "%s at t = %s: expected %s, was %s", node,
                TestNetwork.seconds(time), expected, describe(value)));
    }

    static String describe(Value v) {
        return v == null ? "no value" : v.text() + " (" + v.type() + ")";
    }
}
