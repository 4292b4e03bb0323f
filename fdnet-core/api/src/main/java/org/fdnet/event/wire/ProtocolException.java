package org.fdnet.event.wire;

import java.io.IOException;

/** A peer broke the protocol: bad magic or version, unknown type, oversized, truncated or malformed frame. */
public final class ProtocolException extends IOException {
    public ProtocolException(String message) {
        super(message);
    }
}
