package org.fdnet.logger.ui;

import java.util.ArrayList;
import java.util.List;
import javax.swing.table.AbstractTableModel;
import org.fdnet.logger.server.ClientInfo;

/** The clients of one server: address, port, name, state (waiting / activated / stopped), frames. */
final class ClientTableModel extends AbstractTableModel {
    private static final String[] COLUMNS = {"Client address", "Client port", "Name", "State", "Frames", "Ended because"};
    private List<ClientInfo> clients = new ArrayList<>();

    void update(List<ClientInfo> now) {
        clients = new ArrayList<>(now);
        fireTableDataChanged();
    }

    @Override
    public int getRowCount() {
        return clients.size();
    }

    @Override
    public int getColumnCount() {
        return COLUMNS.length;
    }

    @Override
    public String getColumnName(int column) {
        return COLUMNS[column];
    }

    @Override
    public Object getValueAt(int row, int column) {
        ClientInfo c = clients.get(row);
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
