package org.fdnet.event.wire;

import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;

/**
 * One received frame: its type and a cursor over its payload. Every read checks the payload's bounds and
 * throws a {@link ProtocolException} naming what was missing, so a malformed frame never escapes as a
 * runtime exception.
 */
public final class Frame {
    private final MessageType type;
    private final ByteBuffer payload;

    /**
     * A frame over {@code payload}.
     *
     * @param type    the frame's type
     * @param payload the bytes after the type byte, array-backed, the cursor at their start; not copied
     */
    public Frame(MessageType type, ByteBuffer payload) {
        this.type = type;
        this.payload = payload;
    }

    /**
     * The frame's type.
     *
     * @return the type its first byte named
     */
    public MessageType type() {
        return type;
    }

    /**
     * The payload bytes not yet read.
     *
     * @return the count from the cursor to the end
     */
    public int remaining() {
        return payload.remaining();
    }

    /**
     * Reads a {@code u8}.
     *
     * @return 0 to 255
     * @throws ProtocolException when the payload ends first
     */
    public int getByte() throws ProtocolException {
        try {
            return payload.get() & 0xFF;
        } catch (BufferUnderflowException e) {
            throw malformed("u8");
        }
    }

    /**
     * Reads a big-endian {@code u16}.
     *
     * @return 0 to 65535
     * @throws ProtocolException when the payload ends first
     */
    public int getShort() throws ProtocolException {
        try {
            return payload.getShort() & 0xFFFF;
        } catch (BufferUnderflowException e) {
            throw malformed("u16");
        }
    }

    /**
     * Reads a big-endian {@code i32}.
     *
     * @return the signed value
     * @throws ProtocolException when the payload ends first
     */
    public int getInt() throws ProtocolException {
        try {
            return payload.getInt();
        } catch (BufferUnderflowException e) {
            throw malformed("i32");
        }
    }

    /**
     * Reads a big-endian {@code i64}.
     *
     * @return the signed value
     * @throws ProtocolException when the payload ends first
     */
    public long getLong() throws ProtocolException {
        try {
            return payload.getLong();
        } catch (BufferUnderflowException e) {
            throw malformed("i64");
        }
    }

    /**
     * A count that must be non-negative and able to fit the rest of the payload at minBytesEach: a malformed count
     * cannot make the reader allocate more than the frame could hold.
     *
     * @param minBytesEach the least bytes one counted item takes
     * @return the count, 0 or more
     * @throws ProtocolException when the count is negative or its items could not fit the bytes left
     */
    public int getCount(int minBytesEach) throws ProtocolException {
        int n = getInt();
        if (n < 0 || (long) n * minBytesEach > payload.remaining()) {
            throw new ProtocolException("malformed " + type + " frame: count " + n
                    + " does not fit the " + payload.remaining() + " bytes left");
        }
        return n;
    }

    /**
     * Reads a string: {@code u32 byteLength} then that many UTF-8 bytes.
     *
     * @return the decoded string
     * @throws ProtocolException when the length is negative or runs past the payload
     */
    public String getString() throws ProtocolException {
        int n = getInt();
        if (n < 0 || n > payload.remaining()) {
            throw new ProtocolException("malformed " + type + " frame: string of " + n
                    + " bytes with " + payload.remaining() + " bytes left");
        }
        String s = new String(payload.array(), payload.arrayOffset() + payload.position(), n, StandardCharsets.UTF_8);
        payload.position(payload.position() + n);
        return s;
    }

    /**
     * The next byte, left where it is.
     *
     * @return 0 to 255
     * @throws ProtocolException when no byte is left
     */
    public int peekByte() throws ProtocolException {
        if (!payload.hasRemaining()) {
            throw malformed("u8");
        }
        return payload.get(payload.position()) & 0xFF;
    }

    /**
     * Passes over a string ({@code u32 byteLength, bytes}) and answers where its bytes are in
     * {@link #array()}: a reader that keeps the bytes makes no String.
     *
     * @return the index in {@link #array()} of the string's first byte; it ends at {@link #arrayPosition()}
     * @throws ProtocolException when the length is negative or runs past the payload
     */
    public int skipString() throws ProtocolException {
        int n = getInt();
        if (n < 0 || n > payload.remaining()) {
            throw new ProtocolException("malformed " + type + " frame: string of " + n
                    + " bytes with " + payload.remaining() + " bytes left");
        }
        int at = payload.arrayOffset() + payload.position();
        payload.position(payload.position() + n);
        return at;
    }

    /**
     * Where the next byte is in {@link #array()}: the end of a string just skipped.
     *
     * @return an index into {@link #array()}
     */
    public int arrayPosition() {
        return payload.arrayOffset() + payload.position();
    }

    /**
     * Passes over {@code n} bytes that the caller read from {@link #array()} itself.
     *
     * @param n how many bytes to pass over
     * @throws ProtocolException when {@code n} is negative or more than are left
     */
    public void skip(int n) throws ProtocolException {
        if (n < 0 || n > payload.remaining()) {
            throw new ProtocolException("malformed " + type + " frame: " + n + " bytes expected, " + payload.remaining() + " left");
        }
        payload.position(payload.position() + n);
    }

    /**
     * The bytes left in the payload.
     *
     * @return the count from the cursor to the end (as {@link #remaining()})
     */
    public int remainingBytes() {
        return payload.remaining();
    }

    /**
     * The frame's bytes (not a copy; offsets from {@link #skipString}).
     *
     * @return the backing array; do not change it
     */
    public byte[] array() {
        return payload.array();
    }

    /**
     * Where the cursor is in the payload: with {@link #rewind(int)}, a frame can be checked, then read.
     *
     * @return the cursor's offset in the payload
     */
    public int position() {
        return payload.position();
    }

    /**
     * Puts the cursor back to a {@link #position()} taken earlier.
     *
     * @param position what {@link #position()} returned
     */
    public void rewind(int position) {
        payload.position(position);
    }

    /**
     * Fails if bytes are left over: a frame must be exactly as long as its content.
     *
     * @throws ProtocolException naming the number of trailing bytes
     */
    public void expectEnd() throws ProtocolException {
        if (payload.hasRemaining()) {
            throw new ProtocolException("malformed " + type + " frame: " + payload.remaining() + " unexpected trailing bytes");
        }
    }

    private ProtocolException malformed(String what) {
        return new ProtocolException("malformed " + type + " frame: truncated before a " + what);
    }
}
