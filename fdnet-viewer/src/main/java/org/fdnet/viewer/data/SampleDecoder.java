package org.fdnet.viewer.data;

import org.fdnet.event.DataValueEvent;
import org.fdnet.event.TypedValue;

/**
 * Turns a Data's logged value into numbers: a boolean is 0 or 1, a long and a double are themselves, a
 * vector of doubles gives one number per component. Strings and bytes are not plotted (empty answer), nor is
 * a value the logger could only give back as text; the caller counts them. Values arrive typed (protocol
 * version 2), so nothing is parsed here.
 */
public final class SampleDecoder {
    private static final double[] NONE = new double[0];

    private SampleDecoder() {
    }

    public static double[] numbers(DataValueEvent e) {
        TypedValue v = e.value();
        return switch (v.type()) {
            case BOOLEAN -> new double[] {v.booleanValue() ? 1 : 0};
            case LONG, DOUBLE -> new double[] {v.number()};
            case DOUBLES -> v.doubles();
            case STRING, BYTES -> NONE;
        };
    }
}
