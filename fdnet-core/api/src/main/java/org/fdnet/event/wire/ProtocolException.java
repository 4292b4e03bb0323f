package org.fdnet.event.wire;

import java.io.IOException;

/** A peer broke the protocol: bad magic or version, unknown type, oversized, truncated or malformed frame. */
public final class ProtocolException extends IOException {
    /**
     * A violation.
     *
     * @param message what was wrong, naming the frame type or field
     */
    public ProtocolException(String message) {
        super(message);
    }
}
