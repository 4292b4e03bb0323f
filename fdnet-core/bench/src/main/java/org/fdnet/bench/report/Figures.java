package org.fdnet.bench.report;

import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** How the report writes and reads numbers: thousands separated by commas, about four significant digits. */
final class Figures {
    private static final Pattern NUMBER = Pattern.compile("-?[0-9][0-9,]*(?:\\.[0-9]+)?");

    private Figures() {
    }

    static String format(double x) {
        double a = Math.abs(x);
        String pattern = a >= 100 || a == Math.rint(a) ? "%,.0f" : a >= 10 ? "%,.1f" : a >= 1 ? "%,.2f" : "%,.3f";
        return String.format(Locale.ROOT, pattern, x);
    }

    /** The first number in {@code text} ("1,428.48 ms" gives 1428.48), or NaN when there is none. */
    static double parse(String text) {
        Matcher m = NUMBER.matcher(text);
        return m.find() ? Double.parseDouble(m.group().replace(",", "")) : Double.NaN;
    }
}
