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

    /**
     * Starts a new frame, dropping whatever the previous one held.
     *
     * @param type the frame's type
     * @return this writer, for the put calls
     */
    public FrameWriter begin(MessageType type) {
        pos = 4;
        return putByte(type.code());
    }

    /**
     * Bytes written since {@link #begin}, the type byte included.
     *
     * @return the frame's length as its prefix will say
     */
    public int frameLength() {
        return pos - 4;
    }

    /**
     * Puts a {@code u8}.
     *
     * @param v the value; only its low 8 bits are written
     * @return this writer
     */
    public FrameWriter putByte(int v) {
        ensure(1);
        buf[pos++] = (byte) v;
        return this;
    }

    /**
     * Puts a big-endian {@code u16}.
     *
     * @param v the value; only its low 16 bits are written
     * @return this writer
     */
    public FrameWriter putShort(int v) {
        ensure(2);
        buf[pos++] = (byte) (v >>> 8);
        buf[pos++] = (byte) v;
        return this;
    }

    /**
     * Puts a big-endian {@code i32}.
     *
     * @param v the value
     * @return this writer
     */
    public FrameWriter putInt(int v) {
        ensure(4);
        buf[pos++] = (byte) (v >>> 24);
        buf[pos++] = (byte) (v >>> 16);
        buf[pos++] = (byte) (v >>> 8);
        buf[pos++] = (byte) v;
        return this;
    }

    /**
     * Puts a big-endian {@code i64}.
     *
     * @param v the value
     * @return this writer
     */
    public FrameWriter putLong(long v) {
        putInt((int) (v >>> 32));
        return putInt((int) v);
    }

    /**
     * {@code u32 byteLength, UTF-8 bytes}. ASCII (the common case) is copied in one pass, room reserved once;
     * the first non-ASCII character falls back to the encoder.
     *
     * @param s the string, not null
     * @return this writer
     */
    public FrameWriter putString(String s) {
        int n = s.length();
        ensure(4 + n);
        byte[] b = buf;
        int start = pos + 4;
        int i = 0;
        while (i < n) {
            char c = s.charAt(i);
            if (c >= 0x80) {
                break;
            }
            b[start + i] = (byte) c;
            i++;
        }
        if (i == n) {
            putInt(n);
            pos += n;
            return this;
        }
        byte[] bytes = s.getBytes(StandardCharsets.UTF_8);
        putInt(bytes.length);
        ensure(bytes.length);
        System.arraycopy(bytes, 0, buf, pos, bytes.length);
        pos += bytes.length;
        return this;
    }

    /**
     * {@code u8 kind, i32 source, i64 time}: an event's head, room reserved once.
     *
     * @param kind   the event kind, 1 to 4 ({@link EventCodec})
     * @param source the event's source id
     * @param time   the event's time, µs since the epoch
     * @return this writer
     */
    public FrameWriter putEventHead(int kind, int source, long time) {
        ensure(13);
        byte[] b = buf;
        int p = pos;
        b[p] = (byte) kind;
        b[p + 1] = (byte) (source >>> 24);
        b[p + 2] = (byte) (source >>> 16);
        b[p + 3] = (byte) (source >>> 8);
        b[p + 4] = (byte) source;
        int hi = (int) (time >>> 32);
        int lo = (int) time;
        b[p + 5] = (byte) (hi >>> 24);
        b[p + 6] = (byte) (hi >>> 16);
        b[p + 7] = (byte) (hi >>> 8);
        b[p + 8] = (byte) hi;
        b[p + 9] = (byte) (lo >>> 24);
        b[p + 10] = (byte) (lo >>> 16);
        b[p + 11] = (byte) (lo >>> 8);
        b[p + 12] = (byte) lo;
        pos = p + 13;
        return this;
    }

    /**
     * Where the next byte goes: a mark for {@link #bytesSince}.
     *
     * @return an offset in the frame being built
     */
    public int position() {
        return pos;
    }

    /**
     * A copy of what was put since {@code mark} (from {@link #position}): an encoding to keep and reuse.
     *
     * @param mark what {@link #position} returned, in the same frame
     * @return a new array
     */
    public byte[] bytesSince(int mark) {
        return Arrays.copyOfRange(buf, mark, pos);
    }

    /**
     * Bytes already encoded (e.g. an event kept from {@link #bytesSince}), copied as they are.
     *
     * @param bytes the encoding, no length prefix added
     * @return this writer
     */
    public FrameWriter putBytes(byte[] bytes) {
        ensure(bytes.length);
        System.arraycopy(bytes, 0, buf, pos, bytes.length);
        pos += bytes.length;
        return this;
    }

    /**
     * Writes the frame built since {@link #begin}; the stream is not flushed.
     *
     * @param out the connection's stream
     * @throws IOException when writing fails
     */
    public void writeTo(OutputStream out) throws IOException {
        int length = pos - 4;
        buf[0] = (byte) (length >>> 24);
        buf[1] = (byte) (length >>> 16);
        buf[2] = (byte) (length >>> 8);
        buf[3] = (byte) length;
        out.write(buf, 0, pos);
    }

    /**
     * The frame as bytes (length prefix included): for journals and tests.
     *
     * @return a new array, as {@link #writeTo} would write it
     */
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
