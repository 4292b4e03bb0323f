package org.fdnet.event;

/**
 * The type of a Data's value, stored as {@code typevalue} (a small integer) beside the value's text.
 * The codes are part of the logger's schema and protocol: never renumber them.
 */
public enum ValueType {
    BOOLEAN(1), LONG(2), DOUBLE(3), STRING(4), BYTES(5), DOUBLES(6);

    private final int code;

    ValueType(int code) {
        this.code = code;
    }

    public int code() {
        return code;
    }

    public static ValueType fromCode(int code) {
        for (ValueType t : values()) {
            if (t.code == code) {
                return t;
            }
        }
        throw new IllegalArgumentException("unknown value type code " + code);
    }
}
