package org.fdnet.event.wire;

/** The codes of an ERROR frame. */
public enum ErrorCode {
    /** 1: a malformed, truncated, oversized or unexpected frame; also what an unknown code reads as. */
    PROTOCOL(1),
    /** 2: the peer speaks another protocol version. */
    VERSION(2),
    /** 3: the server already serves its maximum number of clients. */
    TOO_MANY_CLIENTS(3),
    /** 4: the same run connected again on another connection, which takes over. */
    REPLACED(4),
    /** 5: the server is stopping. */
    SHUTTING_DOWN(5),
    /** 6: a request the server will not serve, e.g. a viewer too slow to take its monitored events. */
    BAD_REQUEST(6),
    /** 7: the server failed, e.g. its database is unavailable; retry later. */
    INTERNAL(7);

    private final int code;

    ErrorCode(int code) {
        this.code = code;
    }

    /**
     * The code sent in an ERROR frame.
     *
     * @return 1 to 7, fixed for each constant
     */
    public int code() {
        return code;
    }

    /**
     * The constant of a received code.
     *
     * @param code the ERROR frame's code
     * @return its constant, or {@link #PROTOCOL} for an unknown code
     */
    public static ErrorCode of(int code) {
        for (ErrorCode c : values()) {
            if (c.code == code) {
                return c;
            }
        }
        return PROTOCOL;
    }
}
