package org.fdnet.event.wire;

import java.util.UUID;

/**
 * The first frame of every connection. A core names its run (a UUID chosen when the run starts, so the
 * logger can tell runs apart and resume one after a reconnect) and a human-readable name; a viewer names
 * itself only.
 */
public record Hello(int version, int role, UUID run, String name) {

    public static Hello core(UUID run, String name) {
        return new Hello(Protocol.VERSION, Protocol.ROLE_CORE, run, name);
    }

    public static Hello viewer(String name) {
        return new Hello(Protocol.VERSION, Protocol.ROLE_VIEWER, new UUID(0, 0), name);
    }

    public void write(FrameWriter w) {
        w.begin(MessageType.HELLO).putInt(Protocol.MAGIC).putShort(version).putByte(role)
                .putLong(run.getMostSignificantBits()).putLong(run.getLeastSignificantBits()).putString(name);
    }

    /** Reads and checks a HELLO: the magic, a supported version and a known role. */
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
