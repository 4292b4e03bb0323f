package org.fdnet.logger.export;

import org.fdnet.event.ValueType;

/**
 * JSON of recorded values, written straight from the text the database stores (no parse to a double and back):
 * a Data's message is {@code {"value": V}} with V a JSON boolean, integer, number, string (bytes as Base64) or
 * array of numbers by the value's type; a number that JSON cannot hold ({@code NaN}, {@code Infinity}) or text
 * that is not of its type becomes a string, as its schema allows ({@link MessageSchemas}); a NULL value is null.
 */
final class ValueJson {
    private ValueJson() {
    }

    /** {@code {"value":V}} for a Data value of type {@code type} stored as {@code text}. */
    static void dataMessage(RecordBuffer out, ValueType type, String text) {
        out.ascii("{\"value\":");
        value(out, type, text);
        out.ascii('}');
    }

    static void value(RecordBuffer out, ValueType type, String text) {
        if (text == null) {
            out.ascii("null");
            return;
        }
        switch (type) {
            case BOOLEAN -> {
                if (text.equals("true") || text.equals("false")) {
                    out.ascii(text);
                } else {
                    string(out, text);
                }
            }
            case LONG -> {
                if (isInteger(text)) {
                    out.ascii(text);
                } else {
                    string(out, text);
                }
            }
            case DOUBLE -> number(out, text, 0, text.length());
            case DOUBLES -> {
                out.ascii('[');
                int start = 0;
                int n = text.length();
                while (start < n) {
                    int comma = text.indexOf(',', start);
                    int end = comma < 0 ? n : comma;
                    if (start > 0) {
                        out.ascii(',');
                    }
                    number(out, text, start, end);
                    start = end + 1;
                }
                out.ascii(']');
            }
            case STRING, BYTES -> string(out, text);
        }
    }

    /** A JSON number when the text is one (Java's forms, {@code 1.0E-5} included), else the text as a string. */
    private static void number(RecordBuffer out, String text, int start, int end) {
        if (isNumber(text, start, end)) {
            for (int i = start; i < end; i++) {
                out.ascii(text.charAt(i));
            }
        } else {
            string(out, text.substring(start, end));
        }
    }

    static boolean isInteger(String s) {
        int n = s.length();
        int i = n > 0 && s.charAt(0) == '-' ? 1 : 0;
        if (i == n || n - i > 19 || (s.charAt(i) == '0' && n - i > 1)) {
            return false;
        }
        for (; i < n; i++) {
            char c = s.charAt(i);
            if (c < '0' || c > '9') {
                return false;
            }
        }
        return true;
    }

    /** JSON's number grammar: -?(0|[1-9]d*)(.d+)?([eE][+-]?d+)? */
    static boolean isNumber(String s, int start, int end) {
        int i = start;
        if (i < end && s.charAt(i) == '-') {
            i++;
        }
        int digits = i;
        while (i < end && isDigit(s.charAt(i))) {
            i++;
        }
        if (i == digits || (s.charAt(digits) == '0' && i - digits > 1)) {
            return false;
        }
        if (i < end && s.charAt(i) == '.') {
            int frac = ++i;
            while (i < end && isDigit(s.charAt(i))) {
                i++;
            }
            if (i == frac) {
                return false;
            }
        }
        if (i < end && (s.charAt(i) == 'e' || s.charAt(i) == 'E')) {
            i++;
            if (i < end && (s.charAt(i) == '+' || s.charAt(i) == '-')) {
                i++;
            }
            int exp = i;
            while (i < end && isDigit(s.charAt(i))) {
                i++;
            }
            if (i == exp) {
                return false;
            }
        }
        return i == end;
    }

    private static boolean isDigit(char c) {
        return c >= '0' && c <= '9';
    }

    /** A JSON string: quotes, backslash and control characters escaped, the rest as UTF-8. */
    static void string(RecordBuffer out, String s) {
        out.ascii('"');
        int n = s.length();
        int plain = 0;
        for (int i = 0; i < n; i++) {
            char c = s.charAt(i);
            if (c >= 0x20 && c != '"' && c != '\\' && c < 0x7F) {
                continue;
            }
            if (c >= 0x80) {
                continue; // written as UTF-8 with its run
            }
            if (i > plain) {
                out.utf8(s.substring(plain, i));
            }
            switch (c) {
                case '"' -> out.ascii("\\\"");
                case '\\' -> out.ascii("\\\\");
                case '\n' -> out.ascii("\\n");
                case '\r' -> out.ascii("\\r");
                case '\t' -> out.ascii("\\t");
                default -> out.ascii(String.format("\\u%04x", (int) c));
            }
            plain = i + 1;
        }
        if (n > plain) {
            out.utf8(plain == 0 ? s : s.substring(plain));
        }
        out.ascii('"');
    }
}
