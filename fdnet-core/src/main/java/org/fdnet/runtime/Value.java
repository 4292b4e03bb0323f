package org.fdnet.runtime;

import java.util.Arrays;
import java.util.Base64;
import java.util.Objects;
import java.util.StringJoiner;
import org.fdnet.event.ValueType;
import org.fdnet.netinfo.ParameterType;

/**
 * One value of a Data: its type, its payload, the time it was written (µs since the epoch, from the
 * network's {@link org.fdnet.event.EventClock}; 0 while a Relation is still building it) and its source
 * tick: the number of the newest sensor snapshot it was computed from (0 when none), set by whoever pushes a
 * sensor value ({@link #withTick}) and passed on by the engine — a Relation's outputs get the newest tick of the
 * inputs it read. Immutable: arrays are copied in and out, so a value once published can be shared by every
 * reader without a lock.
 */
public final class Value {
    private final ValueType type;
    private final Object payload;
    private final long time;
    private final long tick;

    private Value(ValueType type, Object payload, long time) {
        this(type, payload, time, 0);
    }

    private Value(ValueType type, Object payload, long time, long tick) {
        this.type = type;
        this.payload = payload;
        this.time = time;
        this.tick = tick;
    }

    public static Value of(boolean b) {
        return new Value(ValueType.BOOLEAN, b, 0);
    }

    public static Value of(long l) {
        return new Value(ValueType.LONG, l, 0);
    }

    public static Value of(double d) {
        return new Value(ValueType.DOUBLE, d, 0);
    }

    public static Value of(String s) {
        return new Value(ValueType.STRING, Objects.requireNonNull(s, "string value"), 0);
    }

    public static Value ofBytes(byte[] bytes) {
        return new Value(ValueType.BYTES, bytes.clone(), 0);
    }

    /** A posture or any vector of doubles. */
    public static Value ofDoubles(double... values) {
        return new Value(ValueType.DOUBLES, values.clone(), 0);
    }

    /** Takes ownership of {@code values} without copying: for the engine and library, which never touch it again. */
    static Value ownDoubles(double[] values) {
        return new Value(ValueType.DOUBLES, values, 0);
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
        Object parsed = parameterType(type).parse(text);
        return new Value(type, parsed, 0);
    }

    public static ParameterType parameterType(ValueType type) {
        return switch (type) {
            case BOOLEAN -> ParameterType.BOOLEAN;
            case LONG -> ParameterType.LONG;
            case DOUBLE -> ParameterType.DOUBLE;
            case STRING -> ParameterType.STRING;
            case BYTES -> ParameterType.BYTES;
            case DOUBLES -> ParameterType.DOUBLES;
        };
    }

    /** The same payload and tick stamped with {@code newTime}. */
    public Value at(long newTime) {
        return new Value(type, payload, newTime, tick);
    }

    /** The same payload and time, computed from sensor snapshot {@code sourceTick} ({@link #tick()}). */
    public Value withTick(long sourceTick) {
        return sourceTick == tick ? this : new Value(type, payload, time, sourceTick);
    }

    /** The newest sensor snapshot this value was computed from (its tick number), 0 when none. */
    public long tick() {
        return tick;
    }

    public ValueType type() {
        return type;
    }

    /** µs since the epoch when the value was written; 0 for a value not yet written. */
    public long time() {
        return time;
    }

    public boolean isScalar() {
        return type != ValueType.DOUBLES && type != ValueType.BYTES && type != ValueType.STRING;
    }

    /** Numbers as they are, booleans as 1/0, a one-element vector as its element. */
    public double asDouble() {
        return switch (type) {
            case DOUBLE -> (Double) payload;
            case LONG -> (Long) payload;
            case BOOLEAN -> ((Boolean) payload) ? 1.0 : 0.0;
            case DOUBLES -> {
                double[] a = (double[]) payload;
                if (a.length == 1) {
                    yield a[0];
                }
                throw new IllegalArgumentException("a vector of " + a.length + " values is not a number");
            }
            case STRING -> {
                try {
                    yield Double.parseDouble(((String) payload).strip());
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("'" + payload + "' is not a number", e);
                }
            }
            case BYTES -> throw new IllegalArgumentException("bytes are not a number");
        };
    }

    public long asLong() {
        if (type == ValueType.LONG) {
            return (Long) payload;
        }
        return Math.round(asDouble());
    }

    /** Booleans as they are; numbers are true when not zero. */
    public boolean asBoolean() {
        if (type == ValueType.BOOLEAN) {
            return (Boolean) payload;
        }
        if (type == ValueType.STRING) {
            return (Boolean) ParameterType.BOOLEAN.parse((String) payload);
        }
        return asDouble() != 0.0;
    }

    /** A copy of the vector; a number becomes a vector of one. */
    public double[] asDoubles() {
        if (type == ValueType.DOUBLES) {
            return ((double[]) payload).clone();
        }
        return new double[] {asDouble()};
    }

    /** Length of a vector, 1 for a scalar. */
    public int length() {
        return type == ValueType.DOUBLES ? ((double[]) payload).length : 1;
    }

    /** Element {@code i} of a vector without copying it (a scalar is a vector of one). */
    public double element(int i) {
        return type == ValueType.DOUBLES ? ((double[]) payload)[i] : asDouble();
    }

    public byte[] asBytes() {
        if (type == ValueType.BYTES) {
            return ((byte[]) payload).clone();
        }
        throw new IllegalArgumentException("a " + type + " value is not bytes");
    }

    /**
     * The text form used in events and files: {@code true}, {@code 42}, {@code 0.5}, the string, Base64
     * for bytes, comma-separated doubles for vectors. {@link #parse} reads it back.
     */
    public String text() {
        return switch (type) {
            case BYTES -> Base64.getEncoder().encodeToString((byte[]) payload);
            case DOUBLES -> {
                StringJoiner j = new StringJoiner(",");
                for (double d : (double[]) payload) {
                    j.add(Double.toString(d));
                }
                yield j.toString();
            }
            default -> payload.toString();
        };
    }

    /** This value converted to {@code target}, or an IllegalArgumentException saying why it cannot be. */
    public Value convertTo(ValueType target) {
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
        if (other == null || other.type != type) {
            return false;
        }
        return switch (type) {
            case DOUBLES -> Arrays.equals((double[]) payload, (double[]) other.payload);
            case BYTES -> Arrays.equals((byte[]) payload, (byte[]) other.payload);
            default -> payload.equals(other.payload);
        };
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Value v && v.time == time && samePayload(v);
    }

    @Override
    public int hashCode() {
        return Objects.hash(type, time, text());
    }

    @Override
    public String toString() {
        return type.name().toLowerCase() + ":" + text() + (time == 0 ? "" : "@" + time);
    }
}
