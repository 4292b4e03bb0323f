package org.fdnet.netinfo;

import java.util.Objects;

/**
 * One node parameter. In the original FDNet a parameter is an anonymous string; FDNet lets a file
 * add a {@code name} and a {@code type} (both optional). A typed parameter's value is checked when it
 * is created, so a model never holds a "long" that is not a number.
 *
 * @param name  the parameter's name, or {@code null} for a positional parameter
 * @param type  the declared type, or {@code null} for an untyped (string) parameter
 * @param value the text exactly as written
 */
public record Parameter(String name, ParameterType type, String value) {
    /**
     * Checks the parts.
     *
     * @param name  the name, or null for a positional parameter
     * @param type  the declared type, or null
     * @param value the text as written
     * @throws NullPointerException     when {@code value} is null
     * @throws IllegalArgumentException when {@code name} is blank or {@code value} is not a text of {@code type}
     */
    public Parameter {
        Objects.requireNonNull(value, "value");
        if (name != null && name.isBlank()) {
            throw new IllegalArgumentException("a parameter name may not be blank");
        }
        if (type != null) {
            type.check(value);
        }
    }

    /**
     * An untyped, unnamed parameter: the original FDNet form.
     *
     * @param value the text
     * @return a parameter without name or type
     */
    public static Parameter of(String value) {
        return new Parameter(null, null, value);
    }

    /**
     * An untyped, named parameter.
     *
     * @param name  the parameter's name, not blank
     * @param value the text
     * @return a parameter without type: a string the node gives meaning
     */
    public static Parameter named(String name, String value) {
        return new Parameter(name, null, value);
    }

    @Override
    public String toString() {
        String typed = type == null ? "" : ":" + type.attribute();
        return (name == null ? "" : name + typed + "=") + value;
    }
}
