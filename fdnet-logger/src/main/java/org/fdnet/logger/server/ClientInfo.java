package org.fdnet.logger.server;

/** One client as the status shows it: address, port, the name it gave, state, frames in, and why it ended. */
public record ClientInfo(String address, int port, String name, ConnectionState state, long frames, String endReason) {
}
