package org.fdnet.event.wire;

import java.util.UUID;

/**
 * The first frame of every connection. A core names its run (a UUID chosen when the run starts, so the
 * logger can tell runs apart and resume one after a reconnect) and a human-readable name; a viewer names
 * itself only. On the wire: {@code u32 magic, u16 version, u8 role, i64 runMost, i64 runLeast, string name}.
 *
 * @param version the protocol version the client speaks
 * @param role    {@link Protocol#ROLE_CORE} or {@link Protocol#ROLE_VIEWER}
 * @param run     a core's run id; all zero for a viewer
 * @param name    a name for people: the core's network or the viewer's
 */
public record Hello(int version, int role, UUID run, String name) {

    /**
     * A core's HELLO at this protocol version.
     *
     * @param run  the run's id, the same on every reconnect of the run
     * @param name the run's name for people
     * @return a HELLO of role core at {@link Protocol#VERSION}
     */
    public static Hello core(UUID run, String name) {
        return new Hello(Protocol.VERSION, Protocol.ROLE_CORE, run, name);
    }

    /**
     * A viewer's HELLO at this protocol version.
     *
     * @param name the viewer's name for people
     * @return a HELLO of role viewer at {@link Protocol#VERSION}, with an all-zero run id
     */
    public static Hello viewer(String name) {
        return new Hello(Protocol.VERSION, Protocol.ROLE_VIEWER, new UUID(0, 0), name);
    }

    /**
     * Appends this frame to {@code w}.
     *
     * @param w the writer to add the frame to
     */
    public void write(FrameWriter w) {
        w.begin(MessageType.HELLO).putInt(Protocol.MAGIC).putShort(version).putByte(role)
                .putLong(run.getMostSignificantBits()).putLong(run.getLeastSignificantBits()).putString(name);
    }

    /**
     * Reads and checks a HELLO: the magic, a known role, no trailing bytes. The version is returned, not checked:
     * the server refuses another version with an ERROR naming both.
     *
     * @param f the first frame of a connection
     * @return the greeting as the client sent it
     * @throws ProtocolException when the frame is not a HELLO, the magic is wrong, the role unknown, or the payload
     *                           malformed
     */
    public static Hello read(Frame f) throws ProtocolException {
        if (f.type() != MessageType.HELLO) {
            throw new ProtocolException("expected HELLO as the first frame, got " + f.type());
        }
        int magic = f.getInt();
        if (magic != Protocol.MAGIC) {
            throw new ProtocolException(String.format("bad magic 0x%08X in HELLO (expected 0x%08X)", magic, Protocol.MAGIC));
        }
        int version = f.getShort();
        int role = f.getByte();
        UUID run = new UUID(f.getLong(), f.getLong());
        String name = f.getString();
        f.expectEnd();
        if (role != Protocol.ROLE_CORE && role != Protocol.ROLE_VIEWER) {
            throw new ProtocolException("unknown role " + role + " in HELLO");
        }
        return new Hello(version, role, run, name);
    }
}
