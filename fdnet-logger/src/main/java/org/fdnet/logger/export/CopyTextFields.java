package org.fdnet.logger.export;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;

/**
 * One row of PostgreSQL's COPY text output split into its fields: tab-separated, {@code \N} for NULL, and the
 * backslash escapes COPY writes ({@code \\ \t \n \r \b \f \v}, octal {@code \ddd}, hex {@code \xhh}) undone in text
 * fields. Numbers are read straight from the bytes. Reused for every row.
 */
final class CopyTextFields {
    private static final int MAX_FIELDS = 16;
    private final int[] start = new int[MAX_FIELDS];
    private final int[] end = new int[MAX_FIELDS];
    private byte[] row;
    private int count;
    private final ByteArrayOutputStream unescaped = new ByteArrayOutputStream();

    /** Splits {@code bytes} (one row, its newline at the end or not). */
    void split(byte[] bytes) {
        row = bytes;
        int n = bytes.length;
        if (n > 0 && bytes[n - 1] == '\n') {
            n--;
        }
        count = 0;
        int s = 0;
        for (int i = 0; i <= n; i++) {
            if (i == n || bytes[i] == '\t') {
                if (count == MAX_FIELDS) {
                    throw new IllegalStateException("a COPY row with more than " + MAX_FIELDS + " fields");
                }
                start[count] = s;
                end[count] = i;
                count++;
                s = i + 1;
            }
        }
    }

    int count() {
        return count;
    }

    boolean isNull(int field) {
        return end[field] - start[field] == 2 && row[start[field]] == '\\' && row[start[field] + 1] == 'N';
    }

    long number(int field) {
        int i = start[field];
        int e = end[field];
        boolean negative = row[i] == '-';
        if (negative) {
            i++;
        }
        long v = 0;
        for (; i < e; i++) {
            int d = row[i] - '0';
            if (d < 0 || d > 9) {
                throw new IllegalStateException("not a number in COPY field " + field + ": "
                        + new String(row, start[field], e - start[field], StandardCharsets.UTF_8));
            }
            v = v * 10 + d;
        }
        return negative ? -v : v;
    }

    /** The field as text, null for NULL. */
    String text(int field) {
        if (isNull(field)) {
            return null;
        }
        int s = start[field];
        int e = end[field];
        int firstEscape = -1;
        for (int i = s; i < e; i++) {
            if (row[i] == '\\') {
                firstEscape = i;
                break;
            }
        }
        if (firstEscape < 0) {
            return new String(row, s, e - s, StandardCharsets.UTF_8);
        }
        unescaped.reset();
        unescaped.write(row, s, firstEscape - s);
        for (int i = firstEscape; i < e; i++) {
            byte b = row[i];
            if (b != '\\' || i + 1 == e) {
                unescaped.write(b);
                continue;
            }
            byte c = row[++i];
            switch (c) {
                case 't' -> unescaped.write('\t');
                case 'n' -> unescaped.write('\n');
                case 'r' -> unescaped.write('\r');
                case 'b' -> unescaped.write('\b');
                case 'f' -> unescaped.write('\f');
                case 'v' -> unescaped.write(0x0B);
                case 'x' -> {
                    int v = 0;
                    int digits = 0;
                    while (digits < 2 && i + 1 < e && Character.digit(row[i + 1], 16) >= 0) {
                        v = v * 16 + Character.digit(row[++i], 16);
                        digits++;
                    }
                    unescaped.write(digits == 0 ? 'x' : v);
                }
                default -> {
                    if (c >= '0' && c <= '7') {
                        int v = c - '0';
                        for (int k = 0; k < 2 && i + 1 < e && row[i + 1] >= '0' && row[i + 1] <= '7'; k++) {
                            v = v * 8 + (row[++i] - '0');
                        }
                        unescaped.write(v);
                    } else {
                        unescaped.write(c); // \\ and any other escaped character stand for themselves
                    }
                }
            }
        }
        return unescaped.toString(StandardCharsets.UTF_8);
    }
}
