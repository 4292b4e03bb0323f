package org.fdnet.hi.text;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Window;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.util.List;

import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.JTextField;
import javax.swing.ListSelectionModel;
import javax.swing.table.DefaultTableModel;

import org.fdnet.hi.edit.NetworkEditor;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.speedy.SpeedyDesign;
import org.fdnet.netinfo.ModuleCounts;

/**
 * The Network frame (thesis Chapter 5 §IX): the network's name (typed anew and Rename: one undoable step) and
 * its modules in numbers — Datas, Relations,
 * Readers and Writers per module and in total — and the module form that adds a module (New), sets an
 * existing one's load-at-start flag (Edit) or deletes it; Open shows a module in the {@link BasicModuleFrame}.
 * A thin view over {@link NetworkSummaryModel}.
 */
public final class NetworkFrame extends JDialog {
    private final transient NetworkEditor editor;
    private final transient SpeedyDesign speedy = new SpeedyDesign();
    private final transient QuietRefresh quiet = new QuietRefresh();
    private final transient NetworkSummaryModel model;

    final JTextField networkName = new JTextField(16);
    final JButton rename = new JButton("Rename");
    final JLabel moduleCount = new JLabel();
    final DefaultTableModel rows = new DefaultTableModel(
            new Object[] {"Module", "Load at start", "Datas", "Relations", "Readers", "Writers"}, 0) {
        @Override
        public boolean isCellEditable(int row, int column) {
            return false;
        }
    };
    final JTable table = new JTable(rows);
    final JLabel total = new JLabel();
    final JTextField moduleName = new JTextField(14);
    final JCheckBox loadAtStart = new JCheckBox("Load at start", true);
    final JButton save = new JButton("New");
    final JButton delete = new JButton("Delete");
    final JButton open = new JButton("Open…");
    final JLabel status = new JLabel(" ");

    public NetworkFrame(Window owner, NetworkEditor editor) {
        super(owner, "Network", ModalityType.MODELESS);
        this.editor = editor;
        model = new NetworkSummaryModel(editor, speedy);
        table.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);

        JPanel info = new JPanel(new FlowLayout(FlowLayout.LEFT, 16, 4));
        info.setBorder(BorderFactory.createTitledBorder("Network information"));
        info.add(new JLabel("Network Name :"));
        networkName.setName("networkName");
        rename.setName("renameNetwork");
        info.add(networkName);
        info.add(rename);
        info.add(moduleCount);

        JScrollPane scroll = new JScrollPane(table);
        scroll.setPreferredSize(new Dimension(560, 160));
        JPanel middle = new JPanel(new BorderLayout(4, 4));
        middle.add(scroll, BorderLayout.CENTER);
        middle.add(total, BorderLayout.SOUTH);

        JPanel form = new JPanel(new FlowLayout(FlowLayout.LEFT));
        form.setBorder(BorderFactory.createTitledBorder("Module information"));
        form.add(new JLabel("Module Name :"));
        form.add(moduleName);
        form.add(loadAtStart);
        form.add(save);
        form.add(delete);
        form.add(open);
        JPanel bottom = new JPanel(new BorderLayout());
        bottom.add(form, BorderLayout.CENTER);
        bottom.add(status, BorderLayout.SOUTH);

        JPanel content = new JPanel(new BorderLayout(6, 6));
        content.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        content.add(info, BorderLayout.NORTH);
        content.add(middle, BorderLayout.CENTER);
        content.add(bottom, BorderLayout.SOUTH);
        setContentPane(content);

        speedy.register("view:rows", this::refreshRows, model.rows());
        speedy.register("view:form", this::refreshForm, model.form());
        wireUserInput();
        speedy.updateAll();

        FrameClosing.finish(this, owner, model::detach);
    }

    public static NetworkFrame open(Window owner, NetworkEditor editor) {
        NetworkFrame frame = new NetworkFrame(owner, editor);
        frame.setVisible(true);
        return frame;
    }

    private void refreshRows() {
        quiet.run(() -> {
            networkName.setText(model.networkName());
            List<NetworkSummaryModel.ModuleRow> list = model.moduleRows();
            moduleCount.setText("Number of modules : " + list.size());
            String selected = selectedModule();
            rows.setRowCount(0);
            for (NetworkSummaryModel.ModuleRow r : list) {
                ModuleCounts c = r.counts();
                rows.addRow(new Object[] {r.name(), r.loadAtStart() ? "yes" : "no", c.datas(), c.relations(),
                        c.readers(), c.writers()});
            }
            for (int i = 0; i < list.size(); i++) {
                if (list.get(i).name().equals(selected)) {
                    table.setRowSelectionInterval(i, i);
                }
            }
            ModuleCounts t = model.total();
            total.setText("Total : " + t.datas() + " Datas, " + t.relations() + " Relations, " + t.readers()
                    + " Readers, " + t.writers() + " Writers");
        });
    }

    private void refreshForm() {
        quiet.run(() -> {
            save.setText(model.saveLabel());
            NetworkSummaryModel.ModuleRow existing = model.existingModule();
            delete.setEnabled(existing != null);
            open.setEnabled(existing != null);
        });
    }

    private String selectedModule() {
        int i = table.getSelectedRow();
        return i >= 0 && i < rows.getRowCount() ? (String) rows.getValueAt(i, 0) : null;
    }

    private void wireUserInput() {
        quiet.onType(moduleName, model::typeModuleName);
        loadAtStart.addActionListener(e -> model.chooseLoadAtStart(loadAtStart.isSelected()));
        table.getSelectionModel().addListSelectionListener(e -> {
            String m = selectedModule();
            if (!e.getValueIsAdjusting() && m != null) {
                quiet.run(() -> moduleName.setText(m));
                loadAtStart.setSelected("yes".equals(rows.getValueAt(table.getSelectedRow(), 1)));
                model.chooseLoadAtStart(loadAtStart.isSelected());
                model.typeModuleName(m);
            }
        });
        table.addMouseListener(new MouseAdapter() {
            @Override
            public void mouseClicked(MouseEvent e) {
                if (e.getClickCount() == 2 && selectedModule() != null) {
                    BasicModuleFrame.open(NetworkFrame.this, editor, selectedModule());
                }
            }
        });
        save.addActionListener(e -> {
            String name = model.typedModuleName();
            boolean adding = model.existingModule() == null;
            show(model.save(), (adding ? "added module " : "set load at start of ") + name);
        });
        delete.addActionListener(e -> {
            String name = model.typedModuleName();
            show(model.delete(name), "deleted module " + name + ", its nodes and every connection to them");
        });
        open.addActionListener(e -> BasicModuleFrame.open(this, editor, model.typedModuleName()));
        rename.addActionListener(e -> renameNetwork());
        networkName.addActionListener(e -> renameNetwork());
    }

    /** The typed name becomes the network's (one undoable step, saved with the network). */
    private void renameNetwork() {
        String typed = networkName.getText();
        show(editor.renameNetwork(typed), "renamed the network to " + typed);
        refreshRows();
    }

    private void show(EditResult r, String done) {
        status.setText(r.accepted() ? done : "Refused: " + r.reason());
    }
}
