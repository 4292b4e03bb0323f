package org.fdnet.event;

/**
 * The type of a Data's value, stored as {@code typevalue} (a small integer) beside the value's text.
 * The codes are part of the logger's schema and protocol: never renumber them.
 */
public enum ValueType {
    /** True or false; code 1. */
    BOOLEAN(1),
    /** A 64-bit whole number; code 2. */
    LONG(2),
    /** A 64-bit floating-point number; code 3. */
    DOUBLE(3),
    /** Text; code 4. */
    STRING(4),
    /** Raw bytes, Base64 in text form; code 5. */
    BYTES(5),
    /** A vector of doubles (a posture, a sensor array), comma-separated in text form; code 6. */
    DOUBLES(6);

    private final int code;

    ValueType(int code) {
        this.code = code;
    }

    /**
     * The code stored as {@code typevalue} and sent on the wire.
     *
     * @return 1 to 6, fixed for each type
     */
    public int code() {
        return code;
    }

    /**
     * The type stored under {@code code}.
     *
     * @param code a {@code typevalue} read from the database or the wire
     * @return the type whose {@link #code()} is {@code code}
     * @throws IllegalArgumentException when no type has that code
     */
    public static ValueType fromCode(int code) {
        for (ValueType t : values()) {
            if (t.code == code) {
                return t;
            }
        }
        throw new IllegalArgumentException("unknown value type code " + code);
    }
}
