package org.fdnet.viewer.data;

import org.fdnet.event.DataValueEvent;

/**
 * Turns a Data's logged value into numbers: a boolean is 0 or 1, a long and a double are themselves, a
 * vector of doubles gives one number per component. Strings and bytes are not plotted (empty answer); a
 * value that does not parse gives an empty answer too, and the caller counts it.
 */
public final class SampleDecoder {
    private static final double[] NONE = new double[0];

    private SampleDecoder() {
    }

    public static double[] numbers(DataValueEvent e) {
        String v = e.value().trim();
        try {
            return switch (e.type()) {
                case BOOLEAN -> new double[] {Boolean.parseBoolean(v) || "1".equals(v) ? 1 : 0};
                case LONG -> new double[] {Long.parseLong(v)};
                case DOUBLE -> new double[] {Double.parseDouble(v)};
                case DOUBLES -> vector(v);
                case STRING, BYTES -> NONE;
            };
        } catch (NumberFormatException bad) {
            return NONE;
        }
    }

    private static double[] vector(String v) {
        String body = v.startsWith("[") && v.endsWith("]") ? v.substring(1, v.length() - 1) : v;
        if (body.isBlank()) {
            return NONE;
        }
        String[] parts = body.trim().split("[\\s,;]+");
        double[] out = new double[parts.length];
        for (int i = 0; i < parts.length; i++) {
            out[i] = Double.parseDouble(parts[i]);
        }
        return out;
    }
}
