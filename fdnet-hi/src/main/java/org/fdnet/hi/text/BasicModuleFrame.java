package org.fdnet.hi.text;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.GridLayout;
import java.awt.Window;
import java.util.List;

import javax.swing.BorderFactory;
import javax.swing.DefaultListModel;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextField;
import javax.swing.ListSelectionModel;

import org.fdnet.hi.edit.NetworkEditor;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.speedy.SpeedyDesign;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ModuleCounts;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;

/**
 * The Basic Module frame (thesis Chapter 5 §IX): one module's name and load-at-start flag, its nodes and
 * connections by name and in numbers; a node or connection can be deleted here, or edited in the
 * {@link AdvancedModuleFrame}. A thin view over {@link ModuleFormModel}.
 */
public final class BasicModuleFrame extends JDialog {
    private final transient NetworkEditor editor;
    private final transient SpeedyDesign speedy = new SpeedyDesign();
    private final transient QuietRefresh quiet = new QuietRefresh();
    private final transient ModuleFormModel model;

    final JTextField moduleName = new JTextField(14);
    final JComboBox<String> loadAtStart = new JComboBox<>(new String[] {"yes", "no"});
    final JButton save = new JButton("Save");
    final JLabel numbers = new JLabel(" ");
    final DefaultListModel<String> nodeRows = new DefaultListModel<>();
    final JList<String> nodeList = new JList<>(nodeRows);
    final DefaultListModel<String> connectionRows = new DefaultListModel<>();
    final JList<String> connectionList = new JList<>(connectionRows);
    final JButton editNode = new JButton("Edit…");
    final JButton deleteNode = new JButton("Delete node");
    final JButton deleteConnection = new JButton("Delete connection");
    final JButton advanced = new JButton("Advanced…");
    final JLabel status = new JLabel(" ");

    public BasicModuleFrame(Window owner, NetworkEditor editor, String module) {
        super(owner, "Module " + module, ModalityType.MODELESS);
        this.editor = editor;
        if (editor.network().module(module) == null) {
            throw new IllegalArgumentException("the network has no module named '" + module + "'");
        }
        model = new ModuleFormModel(editor, module, speedy);
        nodeList.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        connectionList.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);

        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT));
        top.setBorder(BorderFactory.createTitledBorder("Module information"));
        top.add(new JLabel("Module Name :"));
        top.add(moduleName);
        top.add(new JLabel("Load at start :"));
        top.add(loadAtStart);
        top.add(save);

        JPanel lists = new JPanel(new GridLayout(1, 2, 6, 6));
        JScrollPane nodes = new JScrollPane(nodeList);
        nodes.setBorder(BorderFactory.createTitledBorder("Nodes"));
        JScrollPane connections = new JScrollPane(connectionList);
        connections.setBorder(BorderFactory.createTitledBorder("Connections"));
        lists.add(nodes);
        lists.add(connections);
        lists.setPreferredSize(new Dimension(600, 220));

        JPanel middle = new JPanel(new BorderLayout(4, 4));
        middle.add(numbers, BorderLayout.NORTH);
        middle.add(lists, BorderLayout.CENTER);
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.LEFT));
        buttons.add(editNode);
        buttons.add(deleteNode);
        buttons.add(deleteConnection);
        buttons.add(advanced);
        middle.add(buttons, BorderLayout.SOUTH);

        JPanel content = new JPanel(new BorderLayout(6, 6));
        content.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        content.add(top, BorderLayout.NORTH);
        content.add(middle, BorderLayout.CENTER);
        content.add(status, BorderLayout.SOUTH);
        setContentPane(content);

        speedy.register("view:module", this::refresh, model.contents(), model.actions());
        wireUserInput();
        speedy.updateAll();

        FrameClosing.finish(this, owner, model::detach);
    }

    public static BasicModuleFrame open(Window owner, NetworkEditor editor, String module) {
        BasicModuleFrame frame = new BasicModuleFrame(owner, editor, module);
        frame.setVisible(true);
        return frame;
    }

    /** "3 Datas, 2 Relations · 4 Readers, 1 Writer": a module in numbers. */
    static String inNumbers(ModuleCounts c) {
        return c.nodes() + " nodes (" + c.datas() + " Datas, " + c.relations() + " Relations) · "
                + c.connections() + " connections (" + c.readers() + " Readers, " + c.writers() + " Writers)";
    }

    private void refresh() {
        quiet.run(() -> {
            setTitle("Module " + model.module() + (model.exists() ? "" : " (deleted)"));
            QuietRefresh.setText(moduleName, model.typedName());
            loadAtStart.setSelectedItem(model.typedLoadAtStart() ? "yes" : "no");
            String why = model.whyNotSave();
            save.setEnabled(why == null);
            save.setToolTipText(why);
            numbers.setText(model.exists() ? inNumbers(model.counts()) : "this module was deleted");
            int n = nodeList.getSelectedIndex();
            nodeRows.clear();
            for (NodeInfo node : model.nodes()) {
                nodeRows.addElement(node.kind().label() + " " + node.name());
            }
            if (n >= 0 && n < nodeRows.size()) {
                nodeList.setSelectedIndex(n);
            }
            NetworkInfo net = editor.network();
            connectionRows.clear();
            for (ConnectionInfo c : model.connections()) {
                String d = net.referenceText(model.module(), c.data());
                String r = net.referenceText(model.module(), c.relation());
                connectionRows.addElement(c.kind().label() + " " + (c.kind() == org.fdnet.netinfo.ConnectionKind.READER
                        ? d + " → " + r : r + " → " + d));
            }
        });
    }

    private void wireUserInput() {
        quiet.onType(moduleName, model::typeName);
        quiet.onChoose(loadAtStart, s -> model.chooseLoadAtStart("yes".equals(s)));
        save.addActionListener(e -> show(model.save(), "module saved"));
        deleteNode.addActionListener(e -> {
            NodeInfo node = selectedNode();
            if (node == null) {
                status.setText("choose a node in the list first");
                return;
            }
            show(model.deleteNode(node.name()), "deleted " + node.name() + " and its connections");
        });
        deleteConnection.addActionListener(e -> {
            int i = connectionList.getSelectedIndex();
            List<ConnectionInfo> cs = model.connections();
            if (i < 0 || i >= cs.size()) {
                status.setText("choose a connection in the list first");
                return;
            }
            show(model.deleteConnection(cs.get(i)), "connection deleted");
        });
        editNode.addActionListener(e -> {
            NodeInfo node = selectedNode();
            AdvancedModuleFrame frame = AdvancedModuleFrame.open(this, editor, model.module());
            if (node != null) {
                frame.showNode(node.name());
            }
        });
        advanced.addActionListener(e -> AdvancedModuleFrame.open(this, editor, model.module()));
    }

    private NodeInfo selectedNode() {
        int i = nodeList.getSelectedIndex();
        List<NodeInfo> nodes = model.nodes();
        return i >= 0 && i < nodes.size() ? nodes.get(i) : null;
    }

    private void show(EditResult r, String done) {
        status.setText(r.accepted() ? done : "Refused: " + r.reason());
    }
}
