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

    /** A not-yet-written value (time 0, tick 0) of {@code payload}. */
    public static Value of(TypedValue payload) {
        return new Value(Objects.requireNonNull(payload, "payload"), 0, 0);
    }

    public static Value of(boolean b) {
        return of(TypedValue.of(b));
    }

    public static Value of(long l) {
        return of(TypedValue.of(l));
    }

    public static Value of(double d) {
        return of(TypedValue.of(d));
    }

    public static Value of(String s) {
        return of(TypedValue.of(s));
    }

    public static Value ofBytes(byte[] bytes) {
        return of(TypedValue.ofBytes(bytes));
    }

    /** A posture or any vector of doubles. */
    public static Value ofDoubles(double... values) {
        return of(TypedValue.ofDoubles(values));
    }

    /** Takes ownership of {@code values} without copying: for the engine and library, which never touch it again. */
    static Value ownDoubles(double[] values) {
        return of(TypedValue.ownDoubles(values));
    }

    /** The default value of a type: false, 0, 0.0, "", no bytes, an empty vector. */
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

    /** Parses the text form ({@link #text()}, or a parameter's form) of a value of {@code type}. */
    public static Value parse(ValueType type, String text) {
        return of(TypedValue.parse(type, text));
    }

    public static ParameterType parameterType(ValueType type) {
        return TypedValue.parameterType(type);
    }

    /** The same payload and tick stamped with {@code newTime}. */
    public Value at(long newTime) {
        return new Value(payload, newTime, tick);
    }

    /** The same payload and time, computed from sensor snapshot {@code sourceTick} ({@link #tick()}). */
    public Value withTick(long sourceTick) {
        return sourceTick == tick ? this : new Value(payload, time, sourceTick);
    }

    /** The typed payload without time or tick: what this value's event carries (shared, never copied). */
    public TypedValue typed() {
        return payload;
    }

    /** The newest sensor snapshot this value was computed from (its tick number), 0 when none. */
    public long tick() {
        return tick;
    }

    public ValueType type() {
        return payload.type();
    }

    /** µs since the epoch when the value was written; 0 for a value not yet written. */
    public long time() {
        return time;
    }

    public boolean isScalar() {
        ValueType type = payload.type();
        return type != ValueType.DOUBLES && type != ValueType.BYTES && type != ValueType.STRING;
    }

    /** Numbers as they are, booleans as 1/0, a one-element vector as its element. */
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

    public long asLong() {
        if (payload.type() == ValueType.LONG) {
            return payload.longValue();
        }
        return Math.round(asDouble());
    }

    /** Booleans as they are; numbers are true when not zero. */
    public boolean asBoolean() {
        if (payload.type() == ValueType.BOOLEAN) {
            return payload.booleanValue();
        }
        if (payload.type() == ValueType.STRING) {
            return (Boolean) ParameterType.BOOLEAN.parse(payload.stringValue());
        }
        return asDouble() != 0.0;
    }

    /** A copy of the vector; a number becomes a vector of one. */
    public double[] asDoubles() {
        if (payload.type() == ValueType.DOUBLES) {
            return payload.doubles();
        }
        return new double[] {asDouble()};
    }

    /** Length of a vector, 1 for a scalar. */
    public int length() {
        return payload.type() == ValueType.DOUBLES ? payload.length() : 1;
    }

    /** Element {@code i} of a vector without copying it (a scalar is a vector of one). */
    public double element(int i) {
        return payload.type() == ValueType.DOUBLES ? payload.element(i) : asDouble();
    }

    public byte[] asBytes() {
        if (payload.type() == ValueType.BYTES) {
            return payload.bytes();
        }
        throw new IllegalArgumentException("a " + payload.type() + " value is not bytes");
    }

    /**
     * The text form used in files and shown to people: {@code true}, {@code 42}, {@code 0.5}, the string, Base64
     * for bytes, comma-separated doubles for vectors ({@link TypedValue#text()}). {@link #parse} reads it back.
     */
    public String text() {
        return payload.text();
    }

    /** This value converted to {@code target}, or an IllegalArgumentException saying why it cannot be. */
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

    /** Same type and payload (times and ticks may differ). */
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
