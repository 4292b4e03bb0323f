package org.fdnet.event.wire;

/** The codes of an ERROR frame. */
public enum ErrorCode {
    PROTOCOL(1), VERSION(2), TOO_MANY_CLIENTS(3), REPLACED(4), SHUTTING_DOWN(5), BAD_REQUEST(6), INTERNAL(7);

    private final int code;

    ErrorCode(int code) {
        this.code = code;
    }

    public int code() {
        return code;
    }

    public static ErrorCode of(int code) {
        for (ErrorCode c : values()) {
            if (c.code == code) {
                return c;
            }
        }
        return PROTOCOL;
    }
}
