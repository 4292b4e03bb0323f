package org.fdnet.corba;

import org.fdnet.corba.idl.Value;
import org.fdnet.corba.idl.ValueKind;

/**
 * Java values of a running network to IDL {@link Value}s and back. A Data holds one of
 * {@code Boolean, Long, Double, String, byte[], double[]}; {@code Integer}, {@code Short} and {@code Float}
 * widen. Anything else cannot cross hosts and is refused with its type named.
 */
public final class ValueCodec {
    private ValueCodec() {
    }

    public static Value encode(Object value) {
        Value v = new Value();
        if (value instanceof Long l) {
            v.asLong(l);
        } else if (value instanceof Double d) {
            v.asDouble(d);
        } else if (value instanceof String s) {
            v.asString(s);
        } else if (value instanceof Boolean b) {
            v.asBoolean(b);
        } else if (value instanceof double[] ds) {
            v.asDoubles(ds);
        } else if (value instanceof byte[] bs) {
            v.asBytes(bs);
        } else if (value instanceof Integer || value instanceof Short || value instanceof Byte) {
            v.asLong(((Number) value).longValue());
        } else if (value instanceof Float f) {
            v.asDouble(f.doubleValue());
        } else {
            throw new IllegalArgumentException("a value of type "
                    + (value == null ? "null" : value.getClass().getName())
                    + " cannot cross hosts; use boolean, long, double, string, bytes or doubles");
        }
        return v;
    }

    public static Object decode(Value v) {
        return switch (v.discriminator().value()) {
            case ValueKind._VK_BOOLEAN -> v.asBoolean();
            case ValueKind._VK_LONG -> v.asLong();
            case ValueKind._VK_DOUBLE -> v.asDouble();
            case ValueKind._VK_STRING -> v.asString();
            case ValueKind._VK_BYTES -> v.asBytes();
            case ValueKind._VK_DOUBLES -> v.asDoubles();
            default -> throw new IllegalArgumentException("unknown value kind " + v.discriminator().value());
        };
    }

    /** A running network's value as an IDL value. */
    public static Value encode(org.fdnet.runtime.Value value) {
        return encode(RuntimeLocalNetwork.toJava(value));
    }

    /** An IDL value as a running network's value. */
    public static org.fdnet.runtime.Value decodeRuntime(Value v) {
        return RuntimeLocalNetwork.toRuntime(decode(v));
    }
}
