package org.fdnet.layout;

import java.util.regex.Pattern;

/** Colours in .fdg files are {@code #RRGGBB}; this is the one place that says so. */
public final class Colour {
    private static final Pattern HEX = Pattern.compile("#[0-9A-Fa-f]{6}");

    private Colour() {
    }

    /**
     * Checks {@code colour} (which may be {@code null}: no colour).
     *
     * @param colour {@code #RRGGBB} (hexadecimal, either case), or null
     * @return {@code colour} itself, so a setter can check and store in one expression
     * @throws IllegalArgumentException when it is not null and not of the form {@code #RRGGBB}
     */
    public static String check(String colour) {
        if (colour != null && !HEX.matcher(colour).matches()) {
            throw new IllegalArgumentException("colour '" + colour + "' is not of the form #RRGGBB");
        }
        return colour;
    }
}
