package org.fdnet.event.wire;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * Builds one frame at a time in a growable buffer: {@link #begin}, the put methods, then {@link #writeTo}
 * writes {@code u32 length, u8 type, payload} (big-endian) in one call. Not thread-safe: one per connection.
 */
public final class FrameWriter {
    private byte[] buf = new byte[8192];
    private int pos;

    public FrameWriter begin(MessageType type) {
        pos = 4;
        return putByte(type.code());
    }

    /** Bytes written since {@link #begin}, the type byte included. */
    public int frameLength() {
        return pos - 4;
    }

    public FrameWriter putByte(int v) {
        ensure(1);
        buf[pos++] = (byte) v;
        return this;
    }

    public FrameWriter putShort(int v) {
        ensure(2);
        buf[pos++] = (byte) (v >>> 8);
        buf[pos++] = (byte) v;
        return this;
    }

    public FrameWriter putInt(int v) {
        ensure(4);
        buf[pos++] = (byte) (v >>> 24);
        buf[pos++] = (byte) (v >>> 16);
        buf[pos++] = (byte) (v >>> 8);
        buf[pos++] = (byte) v;
        return this;
    }

    public FrameWriter putLong(long v) {
        putInt((int) (v >>> 32));
        return putInt((int) v);
    }

    /** {@code u32 byteLength, UTF-8 bytes}. ASCII (the common case) is copied without an encoder. */
    public FrameWriter putString(String s) {
        int n = s.length();
        boolean ascii = true;
        for (int i = 0; i < n && ascii; i++) {
            ascii = s.charAt(i) < 0x80;
        }
        if (ascii) {
            putInt(n);
            ensure(n);
            for (int i = 0; i < n; i++) {
                buf[pos++] = (byte) s.charAt(i);
            }
            return this;
        }
        byte[] bytes = s.getBytes(StandardCharsets.UTF_8);
        putInt(bytes.length);
        ensure(bytes.length);
        System.arraycopy(bytes, 0, buf, pos, bytes.length);
        pos += bytes.length;
        return this;
    }

    /** Writes the frame built since {@link #begin}; the stream is not flushed. */
    public void writeTo(OutputStream out) throws IOException {
        int length = pos - 4;
        buf[0] = (byte) (length >>> 24);
        buf[1] = (byte) (length >>> 16);
        buf[2] = (byte) (length >>> 8);
        buf[3] = (byte) length;
        out.write(buf, 0, pos);
    }

    /** The frame as bytes (length prefix included): for journals and tests. */
    public byte[] toBytes() {
        int length = pos - 4;
        byte[] copy = Arrays.copyOf(buf, pos);
        copy[0] = (byte) (length >>> 24);
        copy[1] = (byte) (length >>> 16);
        copy[2] = (byte) (length >>> 8);
        copy[3] = (byte) length;
        return copy;
    }

    private void ensure(int n) {
        if (pos + n > buf.length) {
            buf = Arrays.copyOf(buf, Math.max(buf.length * 2, pos + n));
        }
    }
}
