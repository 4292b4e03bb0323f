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

    public Frame(MessageType type, ByteBuffer payload) {
        this.type = type;
        this.payload = payload;
    }

    public MessageType type() {
        return type;
    }

    public int remaining() {
        return payload.remaining();
    }

    public int getByte() throws ProtocolException {
        try {
            return payload.get() & 0xFF;
        } catch (BufferUnderflowException e) {
            throw malformed("u8");
        }
    }

    public int getShort() throws ProtocolException {
        try {
            return payload.getShort() & 0xFFFF;
        } catch (BufferUnderflowException e) {
            throw malformed("u16");
        }
    }

    public int getInt() throws ProtocolException {
        try {
            return payload.getInt();
        } catch (BufferUnderflowException e) {
            throw malformed("i32");
        }
    }

    public long getLong() throws ProtocolException {
        try {
            return payload.getLong();
        } catch (BufferUnderflowException e) {
            throw malformed("i64");
        }
    }

    /** A count that must be non-negative and able to fit the rest of the payload at minBytesEach. */
    public int getCount(int minBytesEach) throws ProtocolException {
        int n = getInt();
        if (n < 0 || (long) n * minBytesEach > payload.remaining()) {
            throw new ProtocolException("malformed " + type + " frame: count " + n
                    + " does not fit the " + payload.remaining() + " bytes left");
        }
        return n;
    }

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

    /** The next byte, left where it is. */
    public int peekByte() throws ProtocolException {
        if (!payload.hasRemaining()) {
            throw malformed("u8");
        }
        return payload.get(payload.position()) & 0xFF;
    }

    /**
     * Passes over a string ({@code u32 byteLength, bytes}) and answers where its bytes are in
     * {@link #array()}: a reader that keeps the bytes makes no String.
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

    /** Where the next byte is in {@link #array()}: the end of a string just skipped. */
    public int arrayPosition() {
        return payload.arrayOffset() + payload.position();
    }

    /** Passes over {@code n} bytes that the caller read from {@link #array()} itself. */
    public void skip(int n) throws ProtocolException {
        if (n < 0 || n > payload.remaining()) {
            throw new ProtocolException("malformed " + type + " frame: " + n + " bytes expected, " + payload.remaining() + " left");
        }
        payload.position(payload.position() + n);
    }

    /** The bytes left in the payload. */
    public int remainingBytes() {
        return payload.remaining();
    }

    /** The frame's bytes (not a copy; offsets from {@link #skipString}). */
    public byte[] array() {
        return payload.array();
    }

    /** Where the cursor is in the payload: with {@link #rewind(int)}, a frame can be checked, then read. */
    public int position() {
        return payload.position();
    }

    /** Puts the cursor back to a {@link #position()} taken earlier. */
    public void rewind(int position) {
        payload.position(position);
    }

    /** Fails if bytes are left over: a frame must be exactly as long as its content. */
    public void expectEnd() throws ProtocolException {
        if (payload.hasRemaining()) {
            throw new ProtocolException("malformed " + type + " frame: " + payload.remaining() + " unexpected trailing bytes");
        }
    }

    private ProtocolException malformed(String what) {
        return new ProtocolException("malformed " + type + " frame: truncated before a " + what);
    }
}
