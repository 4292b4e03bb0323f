package org.fdnet.event;

import java.util.Arrays;
import java.util.Base64;
import java.util.Objects;
import org.fdnet.netinfo.ParameterType;

/**
 * A Data's value as an event carries it: its {@link ValueType} and its payload, typed — a number stays a
 * number from the Relation that wrote it to the logger's COPY and to a viewer's plot. The runtime's
 * {@code Value} holds one of these (plus its time and tick) and hands the same object to its event, so
 * publishing a value inside the commit lock builds no text.
 *
 * <p>Numbers and booleans live in one {@code long} (a double as its bits): no boxing. Strings, bytes and
 * vectors live in {@code ref}. Immutable: arrays are copied in and out, except through {@link #ownDoubles},
 * whose caller promises never to touch the array again.
 *
 * <p>{@link #text()} is the text form the logger stores and files use ({@code true}, {@code 42}, {@code 0.5},
 * the string, Base64 for bytes, comma-separated doubles); {@link #parse} reads it back.
 */
public final class TypedValue {
    private static final TypedValue TRUE = new TypedValue(ValueType.BOOLEAN, 1, null);
    private static final TypedValue FALSE = new TypedValue(ValueType.BOOLEAN, 0, null);

    private final ValueType type;
    private final long bits;
    private final Object ref;

    private TypedValue(ValueType type, long bits, Object ref) {
        this.type = type;
        this.bits = bits;
        this.ref = ref;
    }

    /**
     * A BOOLEAN value.
     *
     * @param b the payload
     * @return one of two shared instances
     */
    public static TypedValue of(boolean b) {
        return b ? TRUE : FALSE;
    }

    /**
     * A LONG value.
     *
     * @param l the payload
     * @return a value of type {@link ValueType#LONG}
     */
    public static TypedValue of(long l) {
        return new TypedValue(ValueType.LONG, l, null);
    }

    /**
     * A DOUBLE value.
     *
     * @param d the payload; every NaN is kept as the one canonical NaN
     * @return a value of type {@link ValueType#DOUBLE}
     */
    public static TypedValue of(double d) {
        return new TypedValue(ValueType.DOUBLE, Double.doubleToLongBits(d), null); // one NaN, as Double.equals has
    }

    /**
     * A STRING value.
     *
     * @param s the payload, not null
     * @return a value of type {@link ValueType#STRING}
     */
    public static TypedValue of(String s) {
        return new TypedValue(ValueType.STRING, 0, Objects.requireNonNull(s, "string value"));
    }

    /**
     * A BYTES value.
     *
     * @param bytes the payload, copied
     * @return a value of type {@link ValueType#BYTES}
     */
    public static TypedValue ofBytes(byte[] bytes) {
        return new TypedValue(ValueType.BYTES, 0, bytes.clone());
    }

    /**
     * A DOUBLES value.
     *
     * @param values the elements, copied
     * @return a value of type {@link ValueType#DOUBLES}
     */
    public static TypedValue ofDoubles(double... values) {
        return new TypedValue(ValueType.DOUBLES, 0, values.clone());
    }

    /**
     * Takes ownership of {@code values} without copying: the caller never touches the array again.
     *
     * @param values the elements, kept as they are
     * @return a value of type {@link ValueType#DOUBLES}
     */
    public static TypedValue ownDoubles(double[] values) {
        return new TypedValue(ValueType.DOUBLES, 0, Objects.requireNonNull(values, "values"));
    }

    /**
     * Takes ownership of {@code bytes} without copying: for decoders that made the array themselves.
     *
     * @param bytes the payload, kept as it is
     * @return a value of type {@link ValueType#BYTES}
     */
    public static TypedValue ownBytes(byte[] bytes) {
        return new TypedValue(ValueType.BYTES, 0, Objects.requireNonNull(bytes, "bytes"));
    }

    /**
     * Parses the text form ({@link #text()}, or a parameter's form) of a value of {@code type}.
     *
     * @param type the type the text is read as
     * @param text the text form; surrounding white space is ignored except for a STRING
     * @return a value of {@code type}
     * @throws IllegalArgumentException naming the text and the expected form
     */
    public static TypedValue parse(ValueType type, String text) {
        Object parsed = parameterType(type).parse(text);
        return switch (type) {
            case BOOLEAN -> of((Boolean) parsed);
            case LONG -> of((Long) parsed);
            case DOUBLE -> of((Double) parsed);
            case STRING -> of((String) parsed);
            case BYTES -> ownBytes((byte[]) parsed);
            case DOUBLES -> ownDoubles((double[]) parsed);
        };
    }

    /**
     * The parameter type whose text form is this value type's.
     *
     * @param type a value type
     * @return the parameter type of the same name
     */
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

    /**
     * The value's type, which decides which accessor may be called.
     *
     * @return the type fixed when the value was made
     */
    public ValueType type() {
        return type;
    }

    /**
     * Whether {@link #number()} holds the value: a {@code LONG} or a {@code DOUBLE} (what a plot draws as one line).
     *
     * @return true for LONG and DOUBLE
     */
    public boolean isNumber() {
        return type == ValueType.LONG || type == ValueType.DOUBLE;
    }

    /**
     * A {@code LONG} or {@code DOUBLE} as a double; an IllegalStateException for any other type.
     *
     * @return the number (a LONG beyond 2^53 loses precision)
     * @throws IllegalStateException when the value is not a number
     */
    public double number() {
        return switch (type) {
            case DOUBLE -> Double.longBitsToDouble(bits);
            case LONG -> bits;
            default -> throw new IllegalStateException("a " + type + " value is not a number");
        };
    }

    /**
     * The payload of a {@code BOOLEAN} value.
     *
     * @return the truth value
     * @throws IllegalStateException for any other type
     */
    public boolean booleanValue() {
        expect(ValueType.BOOLEAN);
        return bits != 0;
    }

    /**
     * The payload of a {@code LONG} value.
     *
     * @return the whole number, exact
     * @throws IllegalStateException for any other type
     */
    public long longValue() {
        expect(ValueType.LONG);
        return bits;
    }

    /**
     * The payload of a {@code DOUBLE} value.
     *
     * @return the number, NaN and infinities included
     * @throws IllegalStateException for any other type
     */
    public double doubleValue() {
        expect(ValueType.DOUBLE);
        return Double.longBitsToDouble(bits);
    }

    /**
     * The payload of a {@code STRING} value.
     *
     * @return the text, never null
     * @throws IllegalStateException for any other type
     */
    public String stringValue() {
        expect(ValueType.STRING);
        return (String) ref;
    }

    /**
     * A copy of a {@code BYTES} value.
     *
     * @return a new array the caller may change
     * @throws IllegalStateException for any other type
     */
    public byte[] bytes() {
        expect(ValueType.BYTES);
        return ((byte[]) ref).clone();
    }

    /**
     * A copy of a {@code DOUBLES} value.
     *
     * @return a new array the caller may change
     * @throws IllegalStateException for any other type
     */
    public double[] doubles() {
        expect(ValueType.DOUBLES);
        return ((double[]) ref).clone();
    }

    /**
     * Elements of a {@code DOUBLES} value, bytes of a {@code BYTES} value, 1 for any other.
     *
     * @return the number of elements or bytes; 1 for a boolean, a number or a string
     */
    public int length() {
        return switch (type) {
            case DOUBLES -> ((double[]) ref).length;
            case BYTES -> ((byte[]) ref).length;
            default -> 1;
        };
    }

    /**
     * Element {@code i} of a {@code DOUBLES} value, without copying the vector.
     *
     * @param i from 0 to {@link #length()} minus one
     * @return the element's value
     * @throws IllegalStateException for any other type
     * @throws IndexOutOfBoundsException when {@code i} is outside the vector
     */
    public double element(int i) {
        expect(ValueType.DOUBLES);
        return ((double[]) ref)[i];
    }

    /**
     * Byte {@code i} of a {@code BYTES} value, without copying them.
     *
     * @param i from 0 to {@link #length()} minus one
     * @return the byte, signed as Java's {@code byte} is
     * @throws IllegalStateException for any other type
     * @throws IndexOutOfBoundsException when {@code i} is outside the bytes
     */
    public byte byteAt(int i) {
        expect(ValueType.BYTES);
        return ((byte[]) ref)[i];
    }

    /**
     * The text form: {@code true}, {@code 42}, {@code 0.5} ({@code Double.toString}), the string, Base64 for
     * bytes, comma-separated doubles for vectors. Made on each call: callers outside the hot paths only.
     *
     * @return the text form, which {@link #parse} reads back to an equal value (except a NaN, which it refuses)
     */
    public String text() {
        return switch (type) {
            case BOOLEAN -> bits != 0 ? "true" : "false";
            case LONG -> Long.toString(bits);
            case DOUBLE -> Double.toString(Double.longBitsToDouble(bits));
            case STRING -> (String) ref;
            case BYTES -> Base64.getEncoder().encodeToString((byte[]) ref);
            case DOUBLES -> {
                double[] a = (double[]) ref;
                StringBuilder b = new StringBuilder(a.length * 8);
                for (int i = 0; i < a.length; i++) {
                    if (i > 0) {
                        b.append(',');
                    }
                    b.append(a[i]);
                }
                yield b.toString();
            }
        };
    }

    private void expect(ValueType wanted) {
        if (type != wanted) {
            throw new IllegalStateException("a " + type + " value read as " + wanted);
        }
    }

    @Override
    public boolean equals(Object o) {
        if (this == o) {
            return true;
        }
        if (!(o instanceof TypedValue v) || v.type != type) {
            return false;
        }
        return switch (type) {
            case DOUBLES -> Arrays.equals((double[]) ref, (double[]) v.ref);
            case BYTES -> Arrays.equals((byte[]) ref, (byte[]) v.ref);
            case STRING -> ref.equals(v.ref);
            default -> bits == v.bits;
        };
    }

    @Override
    public int hashCode() {
        int h = switch (type) {
            case DOUBLES -> Arrays.hashCode((double[]) ref);
            case BYTES -> Arrays.hashCode((byte[]) ref);
            case STRING -> ref.hashCode();
            default -> Long.hashCode(bits);
        };
        return 31 * type.hashCode() + h;
    }

    @Override
    public String toString() {
        return type.name().toLowerCase(java.util.Locale.ROOT) + ":" + text();
    }
}
