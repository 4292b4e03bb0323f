package org.fdnet.event.wire;

import org.fdnet.event.TypedValue;
import org.fdnet.event.ValueType;

/**
 * A Data's value on the wire (protocol version 2): {@code u8 valueType}, then the value in binary —
 * <ul>
 *   <li>1 boolean: {@code u8} 0 or 1</li>
 *   <li>2 long: {@code i64}</li>
 *   <li>3 double: {@code f64} (IEEE 754 bits, big-endian)</li>
 *   <li>4 string: {@code string} ({@code u32 byteLength}, UTF-8)</li>
 *   <li>5 bytes: {@code u32 length}, the bytes</li>
 *   <li>6 doubles: {@code u32 count}, {@code count × f64}</li>
 * </ul>
 * Nothing is formatted or parsed: a number is 8 bytes each way.
 */
public final class ValueCodec {
    /** The encoded size of a {@code LONG} or {@code DOUBLE} value: type byte and 8 bytes. */
    public static final int NUMBER_BYTES = 1 + 8;
    /** The smallest encoded value: a boolean. */
    public static final int MIN_VALUE_BYTES = 2;
    /** {@link ValueType} by code, looked up without {@code values()}'s copy per event (the intake's hot path). */
    private static final ValueType[] VALUE_TYPES = valueTypesByCode();

    private ValueCodec() {
    }

    /**
     * Appends one value to the frame {@code w} is building.
     *
     * @param w a writer inside a frame
     * @param v the value
     */
    public static void write(FrameWriter w, TypedValue v) {
        ValueType type = v.type();
        w.putByte(type.code());
        switch (type) {
            case BOOLEAN -> w.putByte(v.booleanValue() ? 1 : 0);
            case LONG -> w.putLong(v.longValue());
            case DOUBLE -> w.putLong(Double.doubleToRawLongBits(v.doubleValue()));
            case STRING -> w.putString(v.stringValue());
            case BYTES -> {
                int n = v.length();
                w.putInt(n);
                for (int i = 0; i < n; i++) {
                    w.putByte(v.byteAt(i));
                }
            }
            case DOUBLES -> {
                int n = v.length();
                w.putInt(n);
                for (int i = 0; i < n; i++) {
                    w.putLong(Double.doubleToRawLongBits(v.element(i)));
                }
            }
        }
    }

    /**
     * Reads one value at the frame's cursor.
     *
     * @param f a frame positioned on a value
     * @return the value, of the type the frame names; the cursor is after it
     * @throws ProtocolException when the value type is unknown, a boolean is neither 0 nor 1, or the payload ends
     *                           inside the value
     */
    public static TypedValue read(Frame f) throws ProtocolException {
        ValueType type = valueType(f, f.getByte());
        return switch (type) {
            case BOOLEAN -> TypedValue.of(bool(f));
            case LONG -> TypedValue.of(f.getLong());
            case DOUBLE -> TypedValue.of(Double.longBitsToDouble(f.getLong()));
            case STRING -> TypedValue.of(f.getString());
            case BYTES -> {
                int n = f.getCount(1);
                byte[] b = new byte[n];
                System.arraycopy(f.array(), f.arrayPosition(), b, 0, n);
                f.skip(n);
                yield TypedValue.ownBytes(b);
            }
            case DOUBLES -> {
                int n = f.getCount(8);
                double[] a = new double[n];
                for (int i = 0; i < n; i++) {
                    a[i] = Double.longBitsToDouble(f.getLong());
                }
                yield TypedValue.ownDoubles(a);
            }
        };
    }

    /**
     * Steps over one value, checking it exactly as {@link #read} does, and answers its type.
     *
     * @param f a frame positioned on a value; left after it
     * @return the value's type
     * @throws ProtocolException when the value is malformed, as {@link #read} would say
     */
    public static ValueType skip(Frame f) throws ProtocolException {
        ValueType type = valueType(f, f.getByte());
        switch (type) {
            case BOOLEAN -> bool(f);
            case LONG, DOUBLE -> f.getLong(); // as read does: the same message when it is cut short
            case STRING -> f.skipString();
            case BYTES -> f.skip(f.getCount(1));
            case DOUBLES -> f.skip(f.getCount(8) * 8);
        }
        return type;
    }

    private static boolean bool(Frame f) throws ProtocolException {
        int b = f.getByte();
        if (b > 1) {
            throw new ProtocolException("malformed " + f.type() + " frame: boolean value " + b + " (0 or 1)");
        }
        return b == 1;
    }

    /** The value type of {@code code}, or a ProtocolException naming the code and the frame. */
    static ValueType valueType(Frame f, int code) throws ProtocolException {
        ValueType t = code < VALUE_TYPES.length ? VALUE_TYPES[code] : null;
        if (t == null) {
            throw new ProtocolException("malformed " + f.type() + " frame: unknown value type code " + code);
        }
        return t;
    }

    private static ValueType[] valueTypesByCode() {
        int max = 0;
        for (ValueType t : ValueType.values()) {
            max = Math.max(max, t.code());
        }
        ValueType[] byCode = new ValueType[max + 1];
        for (ValueType t : ValueType.values()) {
            byCode[t.code()] = t;
        }
        return byCode;
    }
}
