package org.fdnet.event.wire;

/**
 * An ERROR frame: why the sender is closing the connection. On the wire: {@code u16 code, string message}.
 *
 * @param code    what kind of failure
 * @param message the failure in words, for the peer's log and its user
 */
public record ErrorFrame(ErrorCode code, String message) {

    /**
     * Appends this frame to {@code w}.
     *
     * @param w the writer to add the frame to
     */
    public void write(FrameWriter w) {
        w.begin(MessageType.ERROR).putShort(code.code()).putString(message);
    }

    /**
     * Reads an ERROR frame's payload.
     *
     * @param f a frame of type ERROR, its cursor at the payload's start
     * @return the code ({@link ErrorCode#PROTOCOL} for an unknown one) and the message
     * @throws ProtocolException when the payload is truncated
     */
    public static ErrorFrame read(Frame f) throws ProtocolException {
        return new ErrorFrame(ErrorCode.of(f.getShort()), f.getString());
    }
}
