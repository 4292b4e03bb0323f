package org.fdnet.logger.server;

/** A client connection's state, as the thesis's panels show it. */
public enum ConnectionState {
    /** Accepted; the handshake is not done (or the connection waits for room in the cache). */
    WAITING,
    /** Handshake done; serving. */
    ACTIVATED,
    /** Ended (by the client, a protocol error, or the server stopping). */
    STOPPED;

    public String label() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}
