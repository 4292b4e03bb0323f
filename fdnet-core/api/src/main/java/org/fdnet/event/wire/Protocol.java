package org.fdnet.event.wire;

/**
 * The constants of the logger protocol (see {@code docs/reference/protocol.md}). Version 2: a Data's
 * value travels in binary (version 1 sent it as text; a version-1 peer is refused with both versions named). Every connection starts
 * with a {@link MessageType#HELLO} from the client naming the magic, the version and the role; the server
 * answers {@link MessageType#WELCOME} or {@link MessageType#ERROR} and closes.
 */
public final class Protocol {
    /** {@code "FDNL"}: the first four payload bytes of every HELLO. */
    public static final int MAGIC = 0x46444E4C;
    /** The protocol version this code speaks; a peer of another version is refused. */
    public static final int VERSION = 2;
    /** Largest frame (type byte + payload) a peer may send unless configured otherwise: 1 MiB. */
    public static final int DEFAULT_MAX_FRAME_BYTES = 1 << 20;
    /** The events one EVENTS frame carries at most: keeps frames well under the default maximum. */
    public static final int MAX_EVENTS_PER_FRAME = 2048;
    /**
     * How often the receiver repeats its last ACK to a core while it has committed nothing newer: a core that hears
     * nothing for several of these takes the connection for dead (a silent network drops packets without a reset).
     */
    public static final int ACK_HEARTBEAT_MILLIS = 1000;

    /** A HELLO's role of a core: it sends events. */
    public static final int ROLE_CORE = 1;
    /** A HELLO's role of a viewer: it asks for history and monitors. */
    public static final int ROLE_VIEWER = 2;

    private Protocol() {
    }
}
