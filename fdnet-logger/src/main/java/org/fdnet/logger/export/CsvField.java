package org.fdnet.logger.export;

/** A CSV field (RFC 4180): as it is, or in double quotes (quotes doubled) when it holds a comma, quote or line break. */
public final class CsvField {
    private CsvField() {
    }

    public static String quote(String s) {
        if (s == null) {
            return "";
        }
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == ',' || c == '"' || c == '\n' || c == '\r') {
                return '"' + s.replace("\"", "\"\"") + '"';
            }
        }
        return s;
    }
}
