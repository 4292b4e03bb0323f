package org.fdnet.event.wire;

/** An ERROR frame: why the sender is closing the connection. */
public record ErrorFrame(ErrorCode code, String message) {

    public void write(FrameWriter w) {
        w.begin(MessageType.ERROR).putShort(code.code()).putString(message);
    }

    public static ErrorFrame read(Frame f) throws ProtocolException {
        return new ErrorFrame(ErrorCode.of(f.getShort()), f.getString());
    }
}
