package org.fdnet.logger.export;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * A growable byte buffer that MCAP records and JSON message bodies are built in: little-endian integers,
 * MCAP's length-prefixed strings and byte fields, and plain text. Reused from record to record, so encoding a
 * message allocates nothing once the buffer has grown to the largest record.
 */
final class RecordBuffer {
    private byte[] buf;
    private int len;

    RecordBuffer(int initialCapacity) {
        buf = new byte[Math.max(16, initialCapacity)];
    }

    void clear() {
        len = 0;
    }

    int length() {
        return len;
    }

    byte[] array() {
        return buf;
    }

    byte[] toByteArray() {
        return Arrays.copyOf(buf, len);
    }

    RecordBuffer u8(int v) {
        ensure(1);
        buf[len++] = (byte) v;
        return this;
    }

    RecordBuffer u16(int v) {
        ensure(2);
        buf[len++] = (byte) v;
        buf[len++] = (byte) (v >>> 8);
        return this;
    }

    RecordBuffer u32(long v) {
        ensure(4);
        for (int i = 0; i < 4; i++) {
            buf[len++] = (byte) (v >>> (8 * i));
        }
        return this;
    }

    RecordBuffer u64(long v) {
        ensure(8);
        for (int i = 0; i < 8; i++) {
            buf[len++] = (byte) (v >>> (8 * i));
        }
        return this;
    }

    /** Overwrites 8 bytes at {@code at} (a record's or a field's length known only once its content is written). */
    void u64At(int at, long v) {
        for (int i = 0; i < 8; i++) {
            buf[at + i] = (byte) (v >>> (8 * i));
        }
    }

    void u32At(int at, long v) {
        for (int i = 0; i < 4; i++) {
            buf[at + i] = (byte) (v >>> (8 * i));
        }
    }

    /** MCAP's String: a uint32 byte length, then UTF-8. */
    RecordBuffer string(String s) {
        byte[] b = s.getBytes(StandardCharsets.UTF_8);
        u32(b.length);
        return raw(b, 0, b.length);
    }

    RecordBuffer raw(byte[] b, int off, int n) {
        ensure(n);
        System.arraycopy(b, off, buf, len, n);
        len += n;
        return this;
    }

    RecordBuffer raw(RecordBuffer other) {
        return raw(other.buf, 0, other.len);
    }

    /** Text whose characters are all ASCII (numbers, JSON punctuation, names checked by the caller). */
    RecordBuffer ascii(CharSequence s) {
        int n = s.length();
        ensure(n);
        for (int i = 0; i < n; i++) {
            buf[len++] = (byte) s.charAt(i);
        }
        return this;
    }

    RecordBuffer utf8(String s) {
        byte[] b = s.getBytes(StandardCharsets.UTF_8);
        return raw(b, 0, b.length);
    }

    RecordBuffer ascii(char c) {
        ensure(1);
        buf[len++] = (byte) c;
        return this;
    }

    private void ensure(int n) {
        if (len + n > buf.length) {
            buf = Arrays.copyOf(buf, Math.max(buf.length * 2, len + n));
        }
    }
}
