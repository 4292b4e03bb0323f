package org.fdnet.netinfo;

import java.util.Base64;
import java.util.Locale;

/**
 * The optional declared type of a node parameter (the {@code type} attribute of {@code param}).
 * Untyped parameters are plain strings, as in the original FDNet: the node gives them meaning.
 */
public enum ParameterType {
    /** Any text, kept exactly as written (white space included). */
    STRING,
    /** {@code true}, {@code false}, {@code yes} or {@code no}. */
    BOOLEAN,
    /** A whole number that fits a Java {@code long}. */
    LONG,
    /** A number as Java's {@code Double.parseDouble} reads it, NaN excepted. */
    DOUBLE,
    /** Comma- or space-separated doubles, e.g. a posture: {@code 0.1, 0.2, 0.3}. */
    DOUBLES,
    /** Base64. */
    BYTES;

    /**
     * The attribute value used in files: {@code long}, {@code doubles}, ...
     *
     * @return the lower-case name
     */
    public String attribute() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * The type named by a file's attribute value; {@code null} for no attribute.
     *
     * @param attribute the {@code type} attribute's value, or null when the file gives none
     * @return the type, or null
     * @throws IllegalArgumentException when the value names no type
     */
    public static ParameterType fromAttribute(String attribute) {
        if (attribute == null) {
            return null;
        }
        for (ParameterType type : values()) {
            if (type.attribute().equals(attribute)) {
                return type;
            }
        }
        throw new IllegalArgumentException("unknown parameter type '" + attribute + "'");
    }

    /**
     * Checks that {@code value} is a valid text of this type.
     *
     * @param value the text as written; surrounding white space is ignored (except for STRING)
     * @throws IllegalArgumentException with a message naming the expected form
     */
    public void check(String value) {
        parse(value);
    }

    /**
     * The value converted to its Java form: String, Boolean, Long, Double, double[] or byte[].
     *
     * @param value the text as written; surrounding white space is ignored (except for STRING)
     * @return the parsed value, of the Java class listed above for this type
     * @throws IllegalArgumentException when the text is not of this type, quoting it and naming the expected form
     */
    public Object parse(String value) {
        String text = value.strip();
        switch (this) {
            case STRING:
                return value;
            case BOOLEAN:
                if (text.equals("true") || text.equals("yes")) {
                    return Boolean.TRUE;
                }
                if (text.equals("false") || text.equals("no")) {
                    return Boolean.FALSE;
                }
                throw new IllegalArgumentException("'" + value + "' is not a boolean (true/false/yes/no)");
            case LONG:
                try {
                    return Long.parseLong(text);
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("'" + value + "' is not a whole number", e);
                }
            case DOUBLE:
                return parseDouble(text, value);
            case DOUBLES:
                if (text.isEmpty()) {
                    return new double[0];
                }
                String[] parts = text.split("[,\\s]+");
                double[] result = new double[parts.length];
                for (int i = 0; i < parts.length; i++) {
                    result[i] = parseDouble(parts[i], value);
                }
                return result;
            case BYTES:
                try {
                    return Base64.getDecoder().decode(text);
                } catch (IllegalArgumentException e) {
                    throw new IllegalArgumentException("'" + value + "' is not Base64", e);
                }
            default:
                throw new AssertionError(this);
        }
    }

    private static double parseDouble(String text, String whole) {
        try {
            double d = Double.parseDouble(text);
            if (Double.isNaN(d)) {
                throw new NumberFormatException("NaN");
            }
            return d;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + whole + "' is not a number", e);
        }
    }
}
