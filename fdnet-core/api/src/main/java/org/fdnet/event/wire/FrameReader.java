package org.fdnet.event.wire;

import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;

/**
 * Reads frames from a stream. The length is checked against the maximum before any payload is read, so an
 * oversized frame costs no memory; a stream that ends inside a frame is reported as truncated.
 */
public final class FrameReader {
    private final DataInputStream in;
    private final int maxFrameBytes;

    /**
     * A reader of {@code in}.
     *
     * @param in            the stream, read with no buffering of its own (wrap a socket's stream in a buffer)
     * @param maxFrameBytes the largest frame (type byte and payload) accepted, e.g.
     *                      {@link Protocol#DEFAULT_MAX_FRAME_BYTES}
     */
    public FrameReader(InputStream in, int maxFrameBytes) {
        this.in = new DataInputStream(in);
        this.maxFrameBytes = maxFrameBytes;
    }

    /**
     * The next frame, or {@code null} when the peer closed the stream cleanly between frames. Blocks until a whole
     * frame has arrived.
     *
     * @return the frame, its cursor at the payload's start; or null at a clean end
     * @throws ProtocolException when the length is outside 1 to the maximum, the type is unknown, or the stream ends
     *                           inside a frame
     * @throws IOException       when reading the stream fails
     */
    public Frame read() throws IOException {
        int b0 = in.read();
        if (b0 < 0) {
            return null;
        }
        int length;
        try {
            length = (b0 << 24) | (in.readUnsignedByte() << 16) | (in.readUnsignedByte() << 8) | in.readUnsignedByte();
        } catch (EOFException e) {
            throw new ProtocolException("truncated frame: the stream ended inside a length prefix");
        }
        if (length < 1 || length > maxFrameBytes) {
            throw new ProtocolException("frame length " + Integer.toUnsignedString(length)
                    + " outside 1.." + maxFrameBytes + " bytes");
        }
        byte[] body = new byte[length];
        int read = 0;
        while (read < length) {
            int n = in.read(body, read, length - read);
            if (n < 0) {
                throw new ProtocolException("truncated frame: " + read + " of " + length + " bytes arrived");
            }
            read += n;
        }
        MessageType type = MessageType.of(body[0] & 0xFF);
        return new Frame(type, ByteBuffer.wrap(body, 1, length - 1).slice());
    }
}
