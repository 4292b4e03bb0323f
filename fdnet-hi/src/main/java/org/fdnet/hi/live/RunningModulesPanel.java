package org.fdnet.hi.live;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.GridLayout;
import java.util.Set;
import java.util.function.Function;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.ListSelectionModel;
import javax.swing.table.DefaultTableModel;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.runtime.ChangeOutcome;

/**
 * The module list of a running network: each module of the definition with its state (running, on hold, not
 * loaded), and Load, Unload, Hold and Resume for the selected one. The states come from the network after
 * every settled change ({@link #show}); the buttons send the command and the status bar says how it went.
 */
public final class RunningModulesPanel extends JPanel {
    public static final String RUNNING = "running";
    public static final String HELD = "on hold";
    public static final String NOT_LOADED = "not loaded";

    private final LiveSession session;
    private final NetworkInfo network;
    private final DefaultTableModel rows = new DefaultTableModel(new String[] {"Module", "State"}, 0) {
        @Override
        public boolean isCellEditable(int row, int column) {
            return false;
        }
    };
    private final JTable table = new JTable(rows);

    public RunningModulesPanel(LiveSession session, NetworkInfo network) {
        super(new BorderLayout(0, 4));
        this.session = session;
        this.network = network;
        setBorder(BorderFactory.createTitledBorder("Running modules — " + session.name()));
        table.setName("live.modules");
        table.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        JScrollPane scroll = new JScrollPane(table);
        scroll.setPreferredSize(new Dimension(240, 110));
        add(scroll, BorderLayout.CENTER);
        JPanel buttons = new JPanel(new GridLayout(2, 2, 4, 4));
        buttons.add(button("Load", "live.load", session::load));
        buttons.add(button("Unload", "live.unload", session::unload));
        buttons.add(button("Hold", "live.hold", session::hold));
        buttons.add(button("Resume", "live.resume", session::resume));
        add(buttons, BorderLayout.SOUTH);
    }

    /** The modules of the definition with their states; the selection stays on the same module. */
    public void show(Set<String> loaded, Set<String> held) {
        String selected = selectedModule();
        rows.setRowCount(0);
        for (ModuleInfo m : network.modules()) {
            String name = m.name();
            rows.addRow(new Object[] {name, held.contains(name) ? HELD : loaded.contains(name) ? RUNNING : NOT_LOADED});
            if (name.equals(selected)) {
                table.getSelectionModel().setSelectionInterval(rows.getRowCount() - 1, rows.getRowCount() - 1);
            }
        }
    }

    /** The state shown for {@code module}, or {@code null} when it is not listed. */
    public String stateOf(String module) {
        for (int i = 0; i < rows.getRowCount(); i++) {
            if (rows.getValueAt(i, 0).equals(module)) {
                return (String) rows.getValueAt(i, 1);
            }
        }
        return null;
    }

    /** Selects {@code module}'s row, as a click would. */
    public void select(String module) {
        for (int i = 0; i < rows.getRowCount(); i++) {
            if (rows.getValueAt(i, 0).equals(module)) {
                table.getSelectionModel().setSelectionInterval(i, i);
            }
        }
    }

    private String selectedModule() {
        int row = table.getSelectedRow();
        return row < 0 ? null : (String) rows.getValueAt(row, 0);
    }

    private JButton button(String label, String name, Function<String, ChangeOutcome> command) {
        JButton b = new JButton(label);
        b.setName(name);
        b.addActionListener(e -> {
            String module = selectedModule();
            if (module != null) {
                command.apply(module);
            }
        });
        return b;
    }
}
