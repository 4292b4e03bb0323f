package org.fdnet.hi.live;

import java.util.HashMap;
import java.util.Map;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Value;

/** How a live value is drawn under its node: short enough to fit (4 significant digits, 3 elements, 20 characters). */
final class LiveValueText {
    private static final int MAX_ELEMENTS = 3;
    private static final int MAX_CHARS = 20;

    private LiveValueText() {
    }

    static Map<NodeRef, String> of(Map<NodeRef, Value> latest) {
        Map<NodeRef, String> texts = new HashMap<>();
        latest.forEach((ref, value) -> texts.put(ref, of(value)));
        return texts;
    }

    static String of(Value value) {
        return switch (value.type()) {
            case DOUBLE -> number(value.asDouble());
            case DOUBLES -> elements(value);
            case BYTES -> value.asBytes().length + " bytes";
            default -> shortened(value.text());
        };
    }

    private static String elements(Value value) {
        StringBuilder sb = new StringBuilder("[");
        int shown = Math.min(MAX_ELEMENTS, value.length());
        for (int i = 0; i < shown; i++) {
            sb.append(i == 0 ? "" : ", ").append(number(value.element(i)));
        }
        return sb.append(value.length() > shown ? ", …]" : "]").toString();
    }

    private static String number(double d) {
        return d == Math.rint(d) && Math.abs(d) < 1e6 ? Long.toString((long) d) : String.format(java.util.Locale.ROOT, "%.4g", d);
    }

    private static String shortened(String text) {
        return text.length() <= MAX_CHARS ? text : text.substring(0, MAX_CHARS - 1) + "…";
    }
}
