package org.fdnet.logger.ui;

import org.fdnet.logger.server.ClientInfo;

/** The clients of one server: address, port, name, state (waiting / activated / stopped), frames. */
final class ClientTableModel extends ListTableModel<ClientInfo> {
    ClientTableModel() {
        super("Client address", "Client port", "Name", "State", "Frames", "Ended because");
    }

    @Override
    Object value(ClientInfo c, int column) {
        return switch (column) {
            case 0 -> c.address();
            case 1 -> c.port();
            case 2 -> c.name();
            case 3 -> c.state().label();
            case 4 -> c.frames();
            default -> c.endReason();
        };
    }
}
