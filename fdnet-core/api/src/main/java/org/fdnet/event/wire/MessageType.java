package org.fdnet.event.wire;

/** The frame types of the logger protocol and their one-byte codes (never renumber them). */
public enum MessageType {
    /** client → server: magic, version, role, then role specifics. */
    HELLO(1),
    /** server → client: version; for a core, the last sequence number stored for its run. */
    WELCOME(2),
    /** either way: code and message; the sender closes the connection after it. */
    ERROR(3),
    /** core → logger: first sequence number, count, events. */
    EVENTS(10),
    /** logger → core: every event of the run up to this sequence number is committed. */
    ACK(11),
    /** core → logger, once per connection right after WELCOME: the network run and host its events belong to. */
    RUN(12),
    /** viewer → logger: request id, node ids, from, to. */
    HISTORY(20),
    /** logger → viewer: request id, events (several chunks per request). */
    HISTORY_CHUNK(21),
    /** logger → viewer: request id, total number of events sent. */
    HISTORY_END(22),
    /** viewer → logger: start monitoring node ids. */
    MONITOR(23),
    /** viewer → logger: stop monitoring node ids (none = all). */
    UNMONITOR(24),
    /** logger → viewer: live events of monitored nodes. */
    MONITOR_EVENTS(25),
    /** viewer → logger: request id, name filter ({@code ""}, {@code Node} or {@code Module/Node}). */
    LIST_NODES(26),
    /** logger → viewer: request id, nodes. */
    NODE_LIST(27),
    // 28 was HISTORY_NUMBERS in protocol version 1 (numbers as numbers in plot answers): since version 2 every
    // answer carries values in binary. Not reused, so a stray version-1 request stays an unknown type.
    /** viewer → logger: request id; which streams the logger holds and the network runs they belong to. */
    LIST_RUNS(29),
    /** logger → viewer: request id, streams ({@link LoggedRun}). */
    RUN_LIST(30);

    private final int code;

    MessageType(int code) {
        this.code = code;
    }

    /**
     * The type's byte on the wire.
     *
     * @return the code, fixed for each type
     */
    public int code() {
        return code;
    }

    private static final MessageType[] BY_CODE = new MessageType[256];

    static {
        for (MessageType t : values()) {
            BY_CODE[t.code] = t;
        }
    }

    /**
     * The type of a code, or a {@link ProtocolException} naming the unknown code.
     *
     * @param code a frame's first byte, 0 to 255
     * @return its type
     * @throws ProtocolException when no type has that code
     */
    public static MessageType of(int code) throws ProtocolException {
        MessageType t = code >= 0 && code < 256 ? BY_CODE[code] : null;
        if (t == null) {
            throw new ProtocolException("unknown frame type " + code);
        }
        return t;
    }
}
