package org.fdnet.logger.store;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import org.fdnet.event.TypedValue;

/**
 * Rows in PostgreSQL's COPY text format, built in one reusable byte buffer: tab between columns, newline
 * after each row, and the four characters COPY treats specially (backslash, tab, newline, carriage return)
 * escaped inside text values. A Data's typed value becomes its text here ({@link #value}), straight into the
 * buffer: a number costs no String.
 */
final class CopyRows {
    /** The tens and ones digit of 0..99: numbers are written two digits per division (time stamps have 16). */
    private static final byte[] DIGIT_TENS = new byte[100];
    private static final byte[] DIGIT_ONES = new byte[100];

    static {
        for (int i = 0; i < 100; i++) {
            DIGIT_TENS[i] = (byte) ('0' + i / 10);
            DIGIT_ONES[i] = (byte) ('0' + i % 10);
        }
    }

    private byte[] buf = new byte[1 << 16];
    private int len;
    private boolean rowStarted;

    void clear() {
        len = 0;
        rowStarted = false;
    }

    boolean isEmpty() {
        return len == 0;
    }

    byte[] bytes() {
        return buf;
    }

    int length() {
        return len;
    }

    CopyRows number(long v) {
        separator();
        ensure(20);
        if (v < 0) {
            if (v == Long.MIN_VALUE) {
                byte[] min = Long.toString(v).getBytes(StandardCharsets.US_ASCII);
                System.arraycopy(min, 0, buf, len, min.length);
                len += min.length;
                return this;
            }
            buf[len++] = '-';
            v = -v;
        }
        int end = len + digits(v);
        int at = end;
        while (v >= 100) {
            int pair = (int) (v % 100);
            v /= 100;
            buf[--at] = DIGIT_ONES[pair];
            buf[--at] = DIGIT_TENS[pair];
        }
        int rest = (int) v;
        buf[--at] = DIGIT_ONES[rest];
        if (rest >= 10) {
            buf[--at] = DIGIT_TENS[rest];
        }
        len = end;
        return this;
    }

    /** How many decimal digits a non-negative number has. */
    private static int digits(long v) {
        int n = 1;
        for (long bound = 10; n < 19 && v >= bound; bound *= 10) {
            n++;
        }
        return n;
    }

    CopyRows text(String v) {
        separator();
        int n = v.length();
        ensure(n * 2);
        for (int i = 0; i < n; i++) {
            char c = v.charAt(i);
            if (c >= 0x80) {
                appendUtf8Slow(v.substring(i));
                return this;
            }
            switch (c) {
                case '\\' -> put2('\\', '\\');
                case '\t' -> put2('\\', 't');
                case '\n' -> put2('\\', 'n');
                case '\r' -> put2('\\', 'r');
                default -> buf[len++] = (byte) c;
            }
        }
        return this;
    }

    /** A Data's value in the text form the {@code value} column holds ({@link TypedValue#text()}'s form). */
    CopyRows value(TypedValue v) {
        switch (v.type()) {
            case LONG -> number(v.longValue());
            case DOUBLE -> {
                separator();
                ensure(32);
                len = DoubleText.write(v.doubleValue(), buf, len);
            }
            case DOUBLES -> {
                separator();
                int n = v.length();
                for (int i = 0; i < n; i++) {
                    ensure(33);
                    if (i > 0) {
                        buf[len++] = ',';
                    }
                    len = DoubleText.write(v.element(i), buf, len);
                }
            }
            case BOOLEAN -> text(v.booleanValue() ? "true" : "false");
            case STRING -> text(v.stringValue());
            case BYTES -> text(v.text()); // Base64: no character COPY escapes
        }
        return this;
    }

    void endRow() {
        ensure(1);
        buf[len++] = '\n';
        rowStarted = false;
    }

    private void appendUtf8Slow(String rest) {
        String escaped = rest.replace("\\", "\\\\").replace("\t", "\\t").replace("\n", "\\n").replace("\r", "\\r");
        byte[] b = escaped.getBytes(StandardCharsets.UTF_8);
        ensure(b.length);
        System.arraycopy(b, 0, buf, len, b.length);
        len += b.length;
    }

    private void put2(char a, char b) {
        buf[len++] = (byte) a;
        buf[len++] = (byte) b;
    }

    private void separator() {
        if (rowStarted) {
            ensure(1);
            buf[len++] = '\t';
        }
        rowStarted = true;
    }

    private void ensure(int n) {
        if (len + n > buf.length) {
            buf = Arrays.copyOf(buf, Math.max(buf.length * 2, len + n));
        }
    }
}
