package org.fdnet.logger.ui;

import java.util.ArrayList;
import java.util.List;
import javax.swing.table.AbstractTableModel;

/** A read-only table of one row per element of a list replaced as a whole ({@link #update}); subclasses say what each cell shows. */
abstract class ListTableModel<T> extends AbstractTableModel {
    private final String[] columns;
    private List<T> rows = new ArrayList<>();

    ListTableModel(String... columns) {
        this.columns = columns;
    }

    void update(List<T> now) {
        rows = new ArrayList<>(now);
        fireTableDataChanged();
    }

    /** What the cell of {@code row} in {@code column} shows. */
    abstract Object value(T row, int column);

    @Override
    public final int getRowCount() {
        return rows.size();
    }

    @Override
    public final int getColumnCount() {
        return columns.length;
    }

    @Override
    public final String getColumnName(int column) {
        return columns[column];
    }

    @Override
    public final Object getValueAt(int row, int column) {
        return value(rows.get(row), column);
    }
}
