package org.fdnet.hi.text;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.util.List;
import java.util.function.Consumer;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.ListSelectionModel;
import javax.swing.table.DefaultTableModel;
import org.fdnet.runtime.ParameterSpec;

/**
 * The node tab's list of the parameters the node's class declares — name, default, what is allowed, whether it may
 * change while the network runs, what it does — or why the class cannot be read. Choosing a row offers that
 * parameter to the fields above, for Add.
 */
final class DeclaredParametersTable extends JPanel {
    private static final long serialVersionUID = 1L;

    final DefaultTableModel rows = new DefaultTableModel(
            new Object[] {"Name", "Default", "Allowed", "Live", "Description"}, 0) {
        @Override
        public boolean isCellEditable(int row, int column) {
            return false;
        }
    };
    final JTable table = new JTable(rows);
    final JLabel note = new JLabel(" ");
    private boolean refreshing;

    DeclaredParametersTable() {
        super(new BorderLayout(4, 4));
        setBorder(BorderFactory.createTitledBorder("Declared by the class (choose one to add it)"));
        table.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        table.getColumnModel().getColumn(4).setPreferredWidth(260);
        JScrollPane scroll = new JScrollPane(table);
        scroll.setPreferredSize(new Dimension(560, 100));
        add(scroll, BorderLayout.CENTER);
        add(note, BorderLayout.SOUTH);
    }

    /** Shows {@code declared}, or {@code problem} when the class cannot be read. */
    void show(List<ParameterSpec<?>> declared, String problem) {
        refreshing = true;
        try {
            rows.setRowCount(0);
            for (ParameterSpec<?> spec : declared) {
                rows.addRow(new Object[] {spec.name(), spec.defaultText() == null ? spec.isRequired() ? "required" : ""
                        : spec.defaultText(), spec.requirement(), spec.isLive() ? "yes" : "no", spec.description()});
            }
        } finally {
            refreshing = false;
        }
        note.setText(problem == null ? " " : problem);
    }

    /** Calls {@code chosen} with the name of the parameter the user picks. */
    void onChoose(Consumer<String> chosen) {
        table.getSelectionModel().addListSelectionListener(e -> {
            int row = table.getSelectedRow();
            if (!refreshing && !e.getValueIsAdjusting() && row >= 0) {
                chosen.accept((String) rows.getValueAt(row, 0));
            }
        });
    }
}
