package org.fdnet.hi.app;

import java.awt.BorderLayout;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.JTextField;
import javax.swing.table.DefaultTableModel;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.edit.UndoableNetworkEditor;
import org.fdnet.hi.graph.ConnectionRef;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.hi.graph.SceneListener;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;

/**
 * The node information panel: what the clicked node is (module, name, kind, host, path, class,
 * parameters), or the clicked Reader/Writer. Host, path, class and parameter values of a node, and the
 * name, ends and exist flag of a Reader/Writer, can be changed here (Apply: one undoable edit). Attached to a
 * running network, a Data also has "send a value to the node": the text, in the Data's type, is written into
 * the running Data.
 */
public final class NodeInfoPanel extends JPanel implements SceneListener {
    private final GraphScene scene;
    private final UndoableNetworkEditor editor;
    private final JLabel title = new JLabel("Nothing selected");
    private final JTextField module = readOnly("info.module");
    private final JTextField name = readOnly("info.name");
    private final JTextField host = editable("info.host");
    private final JTextField path = editable("info.path");
    private final JTextField className = editable("info.class");
    private final DefaultTableModel parameters = new DefaultTableModel(new String[] {"Name", "Type", "Value"}, 0) {
        @Override
        public boolean isCellEditable(int row, int column) {
            return column == 2;
        }
    };
    private final JButton applyNode = new JButton("Apply");
    private StatusBar status;
    private JTable paramTable;
    private final JTextField connectionName = new JTextField();
    private final javax.swing.JComboBox<NodeRef> dataEnd = new javax.swing.JComboBox<>();
    private final javax.swing.JComboBox<NodeRef> relationEnd = new javax.swing.JComboBox<>();
    private final JCheckBox exists = new JCheckBox("made at start (exist)");
    private final JButton apply = new JButton("Apply");
    private final JPanel fields = new JPanel(new GridBagLayout());
    private final JTextField sendText = editable("info.sendValue");
    private final JButton send = new JButton("Send");
    private org.fdnet.hi.live.LiveSession live;
    private int row;

    public NodeInfoPanel(GraphScene scene, UndoableNetworkEditor editor) {
        super(new BorderLayout(0, 6));
        this.scene = scene;
        this.editor = editor;
        setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        title.setName("info.title");
        title.putClientProperty("FlatLaf.styleClass", "h3");
        add(title, BorderLayout.NORTH);
        add(fields, BorderLayout.CENTER);
        connectionName.setName("info.connectionName");
        connectionName.setColumns(10);
        dataEnd.setPrototypeDisplayValue(new NodeRef("Module", "a Data name"));
        relationEnd.setPrototypeDisplayValue(new NodeRef("Module", "a Relation name"));
        apply.setName("info.apply");
        apply.addActionListener(e -> applyConnection());
        applyNode.setName("info.applyNode");
        applyNode.addActionListener(e -> applyNode());
        send.setName("info.send");
        send.addActionListener(e -> sendValue());
        sendText.addActionListener(e -> sendValue());
        scene.addListener(this);
        selectionChanged();
    }

    @Override
    public void sceneChanged() {
        // positions and colours are not shown here
    }

    @Override
    public void selectionChanged() {
        fields.removeAll();
        row = 0;
        if (scene.selectedConnection() != null) {
            showConnection(scene.selectedConnection());
        } else if (scene.selection().size() == 1) {
            showNode(scene.selection().iterator().next());
        } else {
            title.setText(scene.selection().isEmpty() ? "Nothing selected" : scene.selection().size() + " nodes selected");
        }
        fields.revalidate();
        fields.repaint();
    }

    private void showNode(NodeRef ref) {
        NodeInfo node = scene.network().node(ref);
        title.setText(node.kind().label() + " " + ref.node());
        module.setText(ref.module());
        name.setText(node.name());
        host.setText(node.host());
        path.setText(node.path());
        className.setText(node.className());
        for (JTextField f : new JTextField[] {module, name, host, path, className}) {
            f.setCaretPosition(0);
        }
        parameters.setRowCount(0);
        for (Parameter p : node.parameters()) {
            parameters.addRow(new Object[] {p.name() == null ? "" : p.name(), p.type() == null ? "" : p.type().attribute(), p.value()});
        }
        addRow("Module", module);
        addRow("Name", name);
        addRow("Host", host);
        addRow("Path", path);
        addRow("Class", className);
        JTable table = new JTable(parameters);
        table.setName("info.parameters");
        table.putClientProperty("terminateEditOnFocusLost", Boolean.TRUE);
        paramTable = table;
        JScrollPane scroll = new JScrollPane(table);
        scroll.setPreferredSize(new java.awt.Dimension(260, 160));
        addWide(new JLabel("Parameters"));
        addWide(scroll);
        addWide(applyNode);
        if (live != null && node.kind() == org.fdnet.netinfo.NodeKind.DATA) {
            JPanel line = new JPanel(new BorderLayout(4, 0));
            line.add(sendText, BorderLayout.CENTER);
            line.add(send, BorderLayout.EAST);
            addWide(new JLabel("Send a value to the node (" + live.name() + ")"));
            addWide(line);
        }
        filler();
    }

    /** Attached: Datas get the "send a value" field; {@code null}: offline. */
    public void setLive(org.fdnet.hi.live.LiveSession session) {
        live = session;
        selectionChanged();
    }

    private void sendValue() {
        if (live == null || scene.selection().size() != 1) {
            return;
        }
        if (live.send(scene.selection().iterator().next(), sendText.getText().trim()).executed()) {
            sendText.selectAll();
        }
    }

    /** Where a value that does not fit its type is reported. */
    public void reportTo(StatusBar bar) {
        status = bar;
    }

    /** Host, path, class and parameter values as typed, as one undoable update of the node. */
    private void applyNode() {
        if (scene.selection().size() != 1) {
            return;
        }
        if (paramTable != null && paramTable.isEditing()) {
            paramTable.getCellEditor().stopCellEditing();
        }
        NodeRef ref = scene.selection().iterator().next();
        NodeInfo node = scene.network().node(ref);
        java.util.List<Parameter> values = new java.util.ArrayList<>();
        try {
            for (int i = 0; i < node.parameters().size(); i++) {
                Parameter p = node.parameters().get(i);
                values.add(new Parameter(p.name(), p.type(), String.valueOf(parameters.getValueAt(i, 2))));
            }
        } catch (IllegalArgumentException e) {
            if (status != null) {
                status.error("Refused: " + e.getMessage());
            }
            return;
        }
        editor.updateNode(ref, new NodeInfo(node.kind(), node.name(), host.getText().trim(), path.getText().trim(),
                className.getText().trim(), values));
    }

    private void showConnection(ConnectionRef c) {
        ConnectionInfo info = c.connection();
        title.setText(info.kind().label());
        addRow("Declared in", text(c.module()));
        fillEnds(dataEnd, org.fdnet.netinfo.NodeKind.DATA, info.data());
        fillEnds(relationEnd, org.fdnet.netinfo.NodeKind.RELATION, info.relation());
        addRow("Data", dataEnd);
        addRow("Relation", relationEnd);
        connectionName.setText(info.name() == null ? "" : info.name());
        exists.setSelected(info.exists());
        addRow("Name", connectionName);
        addWide(exists);
        addWide(apply);
        filler();
    }

    private void applyConnection() {
        ConnectionRef c = scene.selectedConnection();
        if (c == null) {
            return;
        }
        ConnectionInfo old = c.connection();
        String newName = connectionName.getText().isBlank() ? null : connectionName.getText().trim();
        NodeRef data = (NodeRef) dataEnd.getSelectedItem();
        NodeRef relation = (NodeRef) relationEnd.getSelectedItem();
        ConnectionInfo updated = new ConnectionInfo(old.kind(), newName, data, relation, exists.isSelected(),
                old.dataInline() && data.equals(old.data()), old.relationInline() && relation.equals(old.relation()));
        EditResult result = editor.updateConnection(c.module(), old, updated);
        if (result.accepted()) {
            scene.selectConnection(new ConnectionRef(c.module(), updated));
        }
    }

    /** Only nodes of the right kind can be chosen as an end, so a connection always joins a Data and a Relation. */
    private void fillEnds(javax.swing.JComboBox<NodeRef> box, org.fdnet.netinfo.NodeKind kind, NodeRef current) {
        box.removeAllItems();
        for (org.fdnet.netinfo.ModuleInfo m : scene.network().modules()) {
            for (NodeInfo n : m.nodes()) {
                if (n.kind() == kind) {
                    box.addItem(new NodeRef(m.name(), n.name()));
                }
            }
        }
        box.setSelectedItem(current);
    }

    private void addRow(String label, JComponent field) {
        GridBagConstraints l = new GridBagConstraints(0, row, 1, 1, 0, 0, GridBagConstraints.WEST,
                GridBagConstraints.NONE, new Insets(2, 0, 2, 8), 0, 0);
        GridBagConstraints f = new GridBagConstraints(1, row++, 1, 1, 1, 0, GridBagConstraints.WEST,
                GridBagConstraints.HORIZONTAL, new Insets(2, 0, 2, 0), 0, 0);
        fields.add(new JLabel(label), l);
        fields.add(field, f);
    }

    private void addWide(JComponent c) {
        fields.add(c, new GridBagConstraints(0, row++, 2, 1, 1, 0, GridBagConstraints.WEST,
                GridBagConstraints.HORIZONTAL, new Insets(4, 0, 2, 0), 0, 0));
    }

    private void filler() {
        fields.add(new JPanel(), new GridBagConstraints(0, row++, 2, 1, 1, 1, GridBagConstraints.WEST,
                GridBagConstraints.BOTH, new Insets(0, 0, 0, 0), 0, 0));
    }

    private static JTextField readOnly(String name) {
        JTextField f = new JTextField(10);
        f.setEditable(false);
        f.setName(name);
        return f;
    }

    private static JTextField editable(String name) {
        JTextField f = new JTextField(10);
        f.setName(name);
        return f;
    }

    private static JTextField text(String value) {
        JTextField f = readOnly(null);
        f.setText(value);
        return f;
    }
}
