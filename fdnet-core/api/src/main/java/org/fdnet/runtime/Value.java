package org.fdnet.runtime;

import java.util.Objects;
import org.fdnet.event.TypedValue;
import org.fdnet.event.ValueType;
import org.fdnet.netinfo.ParameterType;

/**
 * One value of a Data: its type, its payload, the time it was written (µs since the epoch, from the
 * network's {@link org.fdnet.event.EventClock}; 0 while a Relation is still building it) and its source
 * tick: the number of the newest sensor snapshot it was computed from (0 when none), set by whoever pushes a
 * sensor value ({@link #withTick}) and passed on by the engine — a Relation's outputs get the newest tick of the
 * inputs it read. Immutable: arrays are copied in and out, so a value once published can be shared by every
 * reader without a lock.
 *
 * <p>The payload is a {@link TypedValue}: the very object a {@link org.fdnet.event.DataValueEvent} carries, so
 * publishing a write builds one event and no text (see {@link #typed()}).
 *
 * <pre>{@code
 * Value speed = Value.of(0.25);                          // a DOUBLE, not yet written (time 0)
 * Value posture = Value.ofDoubles(0.0, 0.6, -1.2);       // a DOUBLES vector (copied in)
 * double s = speed.asDouble();                           // 0.25
 * double knee = posture.element(2);                      // -1.2, without copying the vector
 * Value parsed = Value.parse(ValueType.DOUBLES, "0,0.6,-1.2");
 * boolean same = parsed.samePayload(posture);            // true: times and ticks are not compared
 * Value asText = speed.convertTo(ValueType.STRING);      // "0.25"
 * }</pre>
 */
public final class Value {
    private final TypedValue payload;
    private final long time;
    private final long tick;

    private Value(TypedValue payload, long time, long tick) {
        this.payload = payload;
        this.time = time;
        this.tick = tick;
    }

    /**
     * A not-yet-written value (time 0, tick 0) of {@code payload}.
     *
     * @param payload the typed payload, shared (it is immutable); not null
     * @return a value of the payload's type
     * @throws NullPointerException when {@code payload} is null
     */
    public static Value of(TypedValue payload) {
        return new Value(Objects.requireNonNull(payload, "payload"), 0, 0);
    }

    /**
     * A not-yet-written BOOLEAN value.
     *
     * @param b the payload
     * @return a value of type {@link ValueType#BOOLEAN}
     */
    public static Value of(boolean b) {
        return of(TypedValue.of(b));
    }

    /**
     * A not-yet-written LONG value.
     *
     * @param l the payload
     * @return a value of type {@link ValueType#LONG}
     */
    public static Value of(long l) {
        return of(TypedValue.of(l));
    }

    /**
     * A not-yet-written DOUBLE value.
     *
     * @param d the payload; NaN and infinities are kept (a Data may refuse them in {@link Data#accept})
     * @return a value of type {@link ValueType#DOUBLE}
     */
    public static Value of(double d) {
        return of(TypedValue.of(d));
    }

    /**
     * A not-yet-written STRING value.
     *
     * @param s the payload, not null
     * @return a value of type {@link ValueType#STRING}
     */
    public static Value of(String s) {
        return of(TypedValue.of(s));
    }

    /**
     * A not-yet-written BYTES value.
     *
     * @param bytes the payload, copied (later changes to the array do not show)
     * @return a value of type {@link ValueType#BYTES}
     */
    public static Value ofBytes(byte[] bytes) {
        return of(TypedValue.ofBytes(bytes));
    }

    /**
     * A posture or any vector of doubles.
     *
     * @param values the elements, copied (later changes to the array do not show); none gives the empty vector
     * @return a value of type {@link ValueType#DOUBLES}
     */
    public static Value ofDoubles(double... values) {
        return of(TypedValue.ofDoubles(values));
    }

    /** Takes ownership of {@code values} without copying: for the engine and library, which never touch it again. */
    static Value ownDoubles(double[] values) {
        return of(TypedValue.ownDoubles(values));
    }

    /**
     * The default value of a type: false, 0, 0.0, "", no bytes, an empty vector.
     *
     * @param type the type wanted
     * @return a not-yet-written value of {@code type}
     */
    public static Value zero(ValueType type) {
        return switch (type) {
            case BOOLEAN -> of(false);
            case LONG -> of(0L);
            case DOUBLE -> of(0.0);
            case STRING -> of("");
            case BYTES -> ofBytes(new byte[0]);
            case DOUBLES -> ofDoubles();
        };
    }

    /**
     * Parses the text form ({@link #text()}, or a parameter's form) of a value of {@code type}.
     *
     * @param type the type the text is read as
     * @param text the text form, e.g. {@code true}, {@code 42}, {@code 0.5}, {@code 0,0.6,-1.2}
     * @return a not-yet-written value of {@code type}
     * @throws IllegalArgumentException when {@code text} is not a value of {@code type}, saying why
     */
    public static Value parse(ValueType type, String text) {
        return of(TypedValue.parse(type, text));
    }

    /**
     * The parameter type whose text form reads values of {@code type}, e.g. for an editor's field.
     *
     * @param type a value type
     * @return the matching parameter type
     */
    public static ParameterType parameterType(ValueType type) {
        return TypedValue.parameterType(type);
    }

    /**
     * The same payload and tick stamped with {@code newTime}.
     *
     * @param newTime µs since the epoch
     * @return a new value (this one is unchanged)
     */
    public Value at(long newTime) {
        return new Value(payload, newTime, tick);
    }

    /**
     * The same payload and time, computed from sensor snapshot {@code sourceTick} ({@link #tick()}).
     *
     * @param sourceTick the number of the sensor snapshot, 0 for none
     * @return this value when the tick is already {@code sourceTick}, else a new one
     */
    public Value withTick(long sourceTick) {
        return sourceTick == tick ? this : new Value(payload, time, sourceTick);
    }

    /**
     * The typed payload without time or tick: what this value's event carries (shared, never copied).
     *
     * @return the immutable payload
     */
    public TypedValue typed() {
        return payload;
    }

    /**
     * The newest sensor snapshot this value was computed from (its tick number), 0 when none.
     *
     * @return the snapshot number, 0 when no sensor value led to it
     */
    public long tick() {
        return tick;
    }

    /**
     * The payload's type.
     *
     * @return the type, which decides which {@code as…} conversions succeed
     */
    public ValueType type() {
        return payload.type();
    }

    /**
     * µs since the epoch when the value was written; 0 for a value not yet written.
     *
     * @return the commit time on the network's clock, or 0
     */
    public long time() {
        return time;
    }

    /**
     * Whether this is one number or truth value, as opposed to a vector, bytes or a string.
     *
     * @return true for BOOLEAN, LONG and DOUBLE values
     */
    public boolean isScalar() {
        ValueType type = payload.type();
        return type != ValueType.DOUBLES && type != ValueType.BYTES && type != ValueType.STRING;
    }

    /**
     * Numbers as they are, booleans as 1/0, a one-element vector as its element.
     *
     * @return the value as a number; a string is parsed
     * @throws IllegalArgumentException for bytes, a vector of other than one element, or a string that is not a
     *                                  number
     */
    public double asDouble() {
        return switch (payload.type()) {
            case DOUBLE, LONG -> payload.number();
            case BOOLEAN -> payload.booleanValue() ? 1.0 : 0.0;
            case DOUBLES -> {
                if (payload.length() == 1) {
                    yield payload.element(0);
                }
                throw new IllegalArgumentException("a vector of " + payload.length() + " values is not a number");
            }
            case STRING -> {
                try {
                    yield Double.parseDouble(payload.stringValue().strip());
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("'" + payload.stringValue() + "' is not a number", e);
                }
            }
            case BYTES -> throw new IllegalArgumentException("bytes are not a number");
        };
    }

    /**
     * A LONG as it is; anything else through {@link #asDouble()}, rounded to the nearest whole number.
     *
     * @return the value as a whole number
     * @throws IllegalArgumentException when the value is not a number ({@link #asDouble()})
     */
    public long asLong() {
        if (payload.type() == ValueType.LONG) {
            return payload.longValue();
        }
        return Math.round(asDouble());
    }

    /**
     * Booleans as they are; numbers are true when not zero.
     *
     * @return the value as a truth value; a string must be {@code true}, {@code false}, {@code yes} or {@code no}
     * @throws IllegalArgumentException for bytes, a vector of other than one element, or another string
     */
    public boolean asBoolean() {
        if (payload.type() == ValueType.BOOLEAN) {
            return payload.booleanValue();
        }
        if (payload.type() == ValueType.STRING) {
            return (Boolean) ParameterType.BOOLEAN.parse(payload.stringValue());
        }
        return asDouble() != 0.0;
    }

    /**
     * A copy of the vector; a number becomes a vector of one.
     *
     * @return a new array the caller may change
     * @throws IllegalArgumentException when the value is neither a vector nor a number ({@link #asDouble()})
     */
    public double[] asDoubles() {
        if (payload.type() == ValueType.DOUBLES) {
            return payload.doubles();
        }
        return new double[] {asDouble()};
    }

    /**
     * Length of a vector, 1 for a scalar.
     *
     * @return the number of elements of a DOUBLES value, else 1
     */
    public int length() {
        return payload.type() == ValueType.DOUBLES ? payload.length() : 1;
    }

    /**
     * Element {@code i} of a vector without copying it (a scalar is a vector of one).
     *
     * @param i the element's index, from 0 to {@link #length()} minus one (ignored for a scalar)
     * @return the element, or for a scalar {@link #asDouble()}
     * @throws IndexOutOfBoundsException when {@code i} is outside a vector
     */
    public double element(int i) {
        return payload.type() == ValueType.DOUBLES ? payload.element(i) : asDouble();
    }

    /**
     * The payload of a BYTES value.
     *
     * @return a copy the caller may change
     * @throws IllegalArgumentException when the value is not of type BYTES (nothing converts to bytes)
     */
    public byte[] asBytes() {
        if (payload.type() == ValueType.BYTES) {
            return payload.bytes();
        }
        throw new IllegalArgumentException("a " + payload.type() + " value is not bytes");
    }

    /**
     * The text form used in files and shown to people: {@code true}, {@code 42}, {@code 0.5}, the string, Base64
     * for bytes, comma-separated doubles for vectors ({@link TypedValue#text()}). {@link #parse} reads it back.
     *
     * @return the payload as text, without time or tick
     */
    public String text() {
        return payload.text();
    }

    /**
     * This value converted to {@code target}, or an IllegalArgumentException saying why it cannot be. What a
     * Relation writes is converted this way to the type of the Data it writes.
     *
     * @param target the type wanted
     * @return this value when it already is of {@code target}, else a new value with the same time and tick
     * @throws IllegalArgumentException when the value cannot become {@code target} (nothing becomes BYTES; a
     *                                  vector of several elements is not a number)
     */
    public Value convertTo(ValueType target) {
        ValueType type = payload.type();
        if (target == type) {
            return this;
        }
        Value converted = switch (target) {
            case DOUBLE -> of(asDouble());
            case LONG -> of(asLong());
            case BOOLEAN -> of(asBoolean());
            case STRING -> of(text());
            case DOUBLES -> ownDoubles(asDoubles());
            case BYTES -> throw new IllegalArgumentException("a " + type.name().toLowerCase() + " value cannot become bytes");
        };
        return converted.at(time).withTick(tick);
    }

    /**
     * Same type and payload (times and ticks may differ).
     *
     * @param other the value to compare with, may be null
     * @return true when {@code other} is not null and carries an equal typed payload
     */
    public boolean samePayload(Value other) {
        return other != null && payload.equals(other.payload);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Value v && v.time == time && samePayload(v);
    }

    @Override
    public int hashCode() {
        return 31 * payload.hashCode() + Long.hashCode(time);
    }

    @Override
    public String toString() {
        return payload + (time == 0 ? "" : "@" + time);
    }
}
