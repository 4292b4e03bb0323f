package org.fdnet.hi.text;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.awt.Window;
import java.util.List;

import javax.swing.BorderFactory;
import javax.swing.DefaultListModel;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTabbedPane;
import javax.swing.JTable;
import javax.swing.JTextField;
import javax.swing.ListSelectionModel;
import javax.swing.table.DefaultTableModel;

import org.fdnet.hi.edit.NetworkEditor;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.merge.MergeReplaceDialog;
import org.fdnet.hi.speedy.SpeedyDesign;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;

/**
 * The Advanced Module frame (thesis Chapter 5 §IX): everything about one module, down to a node's parameters —
 * the module's name and load-at-start flag; a Nodes tab (kind, name, host, path, class, Save/Update, Delete,
 * Rename (to a used name: Merge/Replace), the classes the network's paths offer, the parameter table with types, and
 * the parameters the class declares, with their descriptions); a Connections tab whose ends are chosen among existing
 * nodes.
 * A thin view: the logic is in {@link ModuleFormModel}, {@link NodeFormModel} and {@link ConnectionFormModel},
 * which share one {@link SpeedyDesign}; each widget registers as a child of the model component it shows.
 */
public final class AdvancedModuleFrame extends JDialog {
    /** What the parameter type list shows for an untyped parameter. */
    static final String UNTYPED = "untyped";

    private final transient NetworkEditor editor;
    private final transient SpeedyDesign speedy = new SpeedyDesign();
    private final transient QuietRefresh quiet = new QuietRefresh();
    private final transient ModuleFormModel moduleModel;
    private final transient NodeFormModel nodeModel;
    private final transient ConnectionFormModel connectionModel;

    // module part
    final JTextField moduleName = new JTextField(14);
    final JComboBox<String> loadAtStart = new JComboBox<>(new String[] {"yes", "no"});
    final JButton saveModule = new JButton("Save");
    // nodes tab
    final JComboBox<NodeKind> nodeKind = new JComboBox<>(NodeKind.values());
    final JTextField nodeName = new JTextField(14);
    final JTextField host = new JTextField(12);
    final JTextField path = new JTextField(12);
    final JTextField className = new JTextField(18);
    final JComboBox<NodeClasses.Choice> classChoice = new JComboBox<>();
    final JButton rescanClasses = new JButton("Rescan");
    final JButton saveNode = new JButton("Save");
    final JButton deleteNode = new JButton("Delete");
    final JTextField newName = new JTextField(14);
    final JButton renameNode = new JButton("Rename");
    final JTextField paramName = new JTextField(10);
    final JComboBox<String> paramType = new JComboBox<>();
    final JTextField paramValue = new JTextField(14);
    final JButton addParam = new JButton("Add");
    final JButton editParam = new JButton("Edit");
    final JButton deleteParam = new JButton("Delete");
    final DefaultTableModel paramRows = new DefaultTableModel(new Object[] {"#", "Name", "Type", "Value"}, 0) {
        @Override
        public boolean isCellEditable(int row, int column) {
            return false;
        }
    };
    final JTable paramTable = new JTable(paramRows);
    final DeclaredParametersTable declared = new DeclaredParametersTable();
    // connections tab
    final JComboBox<ConnectionKind> connectionKind = new JComboBox<>(ConnectionKind.values());
    final JComboBox<String> dataEnd = new JComboBox<>();
    final JComboBox<String> relationEnd = new JComboBox<>();
    final JButton addConnection = new JButton("Add");
    final JButton deleteConnection = new JButton("Delete");
    final DefaultListModel<String> connectionRows = new DefaultListModel<>();
    final JList<String> connectionList = new JList<>(connectionRows);
    final JTabbedPane tabs = new JTabbedPane();
    final JLabel status = new JLabel(" ");

    public AdvancedModuleFrame(Window owner, NetworkEditor editor, String module) {
        super(owner, "Module " + module, ModalityType.MODELESS);
        this.editor = editor;
        if (editor.network().module(module) == null) {
            throw new IllegalArgumentException("the network has no module named '" + module + "'");
        }
        moduleModel = new ModuleFormModel(editor, module, speedy);
        nodeModel = new NodeFormModel(editor, module, speedy);
        connectionModel = new ConnectionFormModel(editor, module, speedy);
        paramType.addItem(UNTYPED);
        for (ParameterType t : ParameterType.values()) {
            paramType.addItem(t.attribute());
        }
        nodeKind.setRenderer(new KindLabels<>(NodeKind::label));
        connectionKind.setRenderer(new KindLabels<>(ConnectionKind::label));
        paramTable.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        connectionList.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);

        JPanel content = new JPanel(new BorderLayout(6, 6));
        content.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        content.add(modulePanel(), BorderLayout.NORTH);
        tabs.addTab("Nodes", nodesPanel());
        tabs.addTab("Connections", connectionsPanel());
        content.add(tabs, BorderLayout.CENTER);
        content.add(status, BorderLayout.SOUTH);
        setContentPane(content);

        registerWidgets();
        wireUserInput();
        speedy.updateAll();

        setMinimumSize(new Dimension(640, 460));
        FrameClosing.finish(this, owner, () -> {
            moduleModel.detach();
            nodeModel.detach();
            connectionModel.detach();
        });
    }

    /** Opens (shows) the frame for {@code module}. */
    public static AdvancedModuleFrame open(Window owner, NetworkEditor editor, String module) {
        AdvancedModuleFrame frame = new AdvancedModuleFrame(owner, editor, module);
        frame.setVisible(true);
        return frame;
    }

    /** Shows the node tab with {@code node} loaded, as if the user had typed its name. */
    public void showNode(String node) {
        tabs.setSelectedIndex(0);
        nodeName.setText(node);
    }

    // ------------------------------------------------------------------ layout

    private JComponent modulePanel() {
        JPanel p = new JPanel(new FlowLayout(FlowLayout.LEFT));
        p.setBorder(BorderFactory.createTitledBorder("Module information"));
        p.add(new JLabel("Module Name :"));
        p.add(moduleName);
        p.add(new JLabel("Load at start :"));
        p.add(loadAtStart);
        p.add(saveModule);
        return p;
    }

    private JComponent nodesPanel() {
        JPanel node = new JPanel(new GridBagLayout());
        node.setBorder(BorderFactory.createTitledBorder("Node"));
        row(node, 0, "Type :", nodeKind, "Host :", host, saveNode);
        row(node, 1, "Name :", nodeName, "Path :", path, deleteNode);
        row(node, 2, "Rename to :", newName, "Class :", className, renameNode);
        classChoice.setToolTipText("the Data or Relation classes the network's paths hold; choosing one sets path and class");
        row(node, 3, null, null, "On the paths :", classChoice, rescanClasses);

        JPanel params = new JPanel(new BorderLayout(4, 4));
        params.setBorder(BorderFactory.createTitledBorder("Parameters"));
        JPanel form = new JPanel(new GridBagLayout());
        row(form, 0, "Name :", paramName, "Type :", paramType, addParam);
        row(form, 1, "Value :", paramValue, null, null, editParam);
        row(form, 2, null, null, null, null, deleteParam);
        params.add(form, BorderLayout.NORTH);
        JScrollPane scroll = new JScrollPane(paramTable);
        scroll.setPreferredSize(new Dimension(560, 110));
        params.add(scroll, BorderLayout.CENTER);
        params.add(declared, BorderLayout.SOUTH);

        JPanel p = new JPanel(new BorderLayout(4, 4));
        p.add(node, BorderLayout.NORTH);
        p.add(params, BorderLayout.CENTER);
        return p;
    }

    private JComponent connectionsPanel() {
        JPanel form = new JPanel(new GridBagLayout());
        form.setBorder(BorderFactory.createTitledBorder("Connection (ends are existing nodes)"));
        row(form, 0, "Type :", connectionKind, "Data :", dataEnd, addConnection);
        row(form, 1, null, null, "Relation :", relationEnd, deleteConnection);
        dataEnd.setPrototypeDisplayValue("Module/SomeLongDataName");
        relationEnd.setPrototypeDisplayValue("Module/SomeLongDataName");
        JPanel p = new JPanel(new BorderLayout(4, 4));
        p.add(form, BorderLayout.NORTH);
        p.add(new JScrollPane(connectionList), BorderLayout.CENTER);
        return p;
    }

    private static void row(JPanel panel, int y, String l1, JComponent c1, String l2, JComponent c2, JComponent button) {
        GridBagConstraints g = new GridBagConstraints();
        g.gridy = y;
        g.insets = new Insets(2, 4, 2, 4);
        g.anchor = GridBagConstraints.WEST;
        g.fill = GridBagConstraints.HORIZONTAL;
        g.gridx = 0;
        panel.add(new JLabel(l1 == null ? "" : l1), g);
        g.gridx = 1;
        g.weightx = 0.5;
        panel.add(c1 == null ? new JLabel() : c1, g);
        g.gridx = 2;
        g.weightx = 0;
        panel.add(new JLabel(l2 == null ? "" : l2), g);
        g.gridx = 3;
        g.weightx = 0.5;
        panel.add(c2 == null ? new JLabel() : c2, g);
        g.gridx = 4;
        g.weightx = 0;
        panel.add(button, g);
    }

    // ------------------------------------------------------------------ SpeedyDesign: widgets follow the models

    private void registerWidgets() {
        speedy.register("view:module", () -> quiet.run(() -> {
            setTitle("Module " + moduleModel.module() + (moduleModel.exists() ? "" : " (deleted)"));
            QuietRefresh.setText(moduleName, moduleModel.typedName());
            loadAtStart.setSelectedItem(moduleModel.typedLoadAtStart() ? "yes" : "no");
            String why = moduleModel.whyNotSave();
            saveModule.setEnabled(why == null);
            saveModule.setToolTipText(why);
        }), moduleModel.contents(), moduleModel.actions());

        speedy.register("view:node details", () -> quiet.run(() -> {
            nodeKind.setSelectedItem(nodeModel.kind());
            QuietRefresh.setText(host, nodeModel.host());
            QuietRefresh.setText(path, nodeModel.path());
            QuietRefresh.setText(className, nodeModel.className());
            int selected = paramTable.getSelectedRow();
            paramRows.setRowCount(0);
            List<Parameter> ps = nodeModel.parameters();
            for (int i = 0; i < ps.size(); i++) {
                Parameter p = ps.get(i);
                paramRows.addRow(new Object[] {i + 1, p.name() == null ? "" : p.name(),
                        p.type() == null ? UNTYPED : p.type().attribute(), p.value()});
            }
            if (selected >= 0 && selected < ps.size()) {
                paramTable.setRowSelectionInterval(selected, selected);
            }
            List<NodeClasses.Choice> choices = nodeModel.classChoices();
            NodeClasses.Choice current = choices.stream().filter(c -> c.className().equals(nodeModel.className())
                    && c.path().equals(nodeModel.path())).findFirst().orElse(null);
            QuietRefresh.setItems(classChoice, choices, current);
            String scanProblem = nodeModel.classScanProblem();
            classChoice.setToolTipText(scanProblem != null ? scanProblem : choices.isEmpty()
                    ? "no Data or Relation class on the network's paths" : "choosing one sets path and class");
            declared.show(nodeModel.declaredParameters(), nodeModel.declaredProblem());
        }), nodeModel.details());

        speedy.register("view:node actions", () -> quiet.run(() -> {
            saveNode.setText(nodeModel.saveLabel());
            String why = nodeModel.whyNotSave();
            saveNode.setEnabled(why == null);
            saveNode.setToolTipText(why);
            deleteNode.setEnabled(nodeModel.canDelete());
            renameNode.setEnabled(nodeModel.canDelete());
        }), nodeModel.actions());

        speedy.register("view:connection choices", () -> quiet.run(() -> {
            QuietRefresh.setItems(dataEnd, connectionModel.dataChoices(), connectionModel.data());
            QuietRefresh.setItems(relationEnd, connectionModel.relationChoices(), connectionModel.relation());
            int selected = connectionList.getSelectedIndex();
            connectionRows.clear();
            for (ConnectionInfo c : connectionModel.connections()) {
                connectionRows.addElement(connectionModel.describe(c));
            }
            if (selected >= 0 && selected < connectionRows.size()) {
                connectionList.setSelectedIndex(selected);
            }
        }), connectionModel.choices());

        speedy.register("view:connection actions", () -> quiet.run(() -> {
            String why = connectionModel.whyNotAdd();
            addConnection.setEnabled(why == null);
            addConnection.setToolTipText(why);
        }), connectionModel.actions());
    }

    // ------------------------------------------------------------------ user input goes to the models

    private void wireUserInput() {
        quiet.onType(moduleName, moduleModel::typeName);
        quiet.onChoose(loadAtStart, s -> moduleModel.chooseLoadAtStart("yes".equals(s)));
        saveModule.addActionListener(e -> show(moduleModel.save(), "module saved"));

        quiet.onType(nodeName, nodeModel::typeName);
        quiet.onChoose(nodeKind, k -> {
            if (k != null) {
                nodeModel.chooseKind(k);
            }
        });
        quiet.onType(host, nodeModel::typeHost);
        quiet.onType(path, nodeModel::typePath);
        quiet.onType(className, nodeModel::typeClass);
        quiet.onChoose(classChoice, c -> {
            if (c != null) {
                nodeModel.chooseClass(c);
            }
        });
        rescanClasses.addActionListener(e -> nodeModel.rescanClasses());
        declared.onChoose(name -> {
            NodeFormModel.Offer offer = nodeModel.offered(name);
            if (offer != null) {
                paramName.setText(offer.name());
                paramType.setSelectedItem(offer.type() == null ? UNTYPED : offer.type().attribute());
                paramValue.setText(offer.value());
                status.setText("parameter '" + name + "' offered: give its value, then Add");
            }
        });
        saveNode.addActionListener(e -> {
            boolean update = nodeModel.loaded() != null;
            String name = nodeModel.name();
            EditResult r = nodeModel.save();
            show(r, (update ? "updated " : "added ") + nodeModel.module() + "/" + name);
            if (r.accepted()) {
                nodeModel.typeName(name); // the node exists now: Save turns into Update
            }
        });
        deleteNode.addActionListener(e -> {
            String name = nodeModel.name();
            show(nodeModel.delete(), "deleted " + nodeModel.module() + "/" + name + " and its connections");
        });
        renameNode.addActionListener(e -> rename());

        paramTable.getSelectionModel().addListSelectionListener(e -> {
            int row = paramTable.getSelectedRow();
            List<Parameter> ps = nodeModel.parameters();
            if (!e.getValueIsAdjusting() && row >= 0 && row < ps.size()) {
                Parameter p = ps.get(row);
                paramName.setText(p.name() == null ? "" : p.name());
                paramType.setSelectedItem(p.type() == null ? UNTYPED : p.type().attribute());
                paramValue.setText(p.value());
            }
        });
        addParam.addActionListener(e -> showParameter(nodeModel.addParameter(paramName.getText(), chosenType(),
                paramValue.getText())));
        editParam.addActionListener(e -> showParameter(nodeModel.editParameter(paramTable.getSelectedRow(),
                paramName.getText(), chosenType(), paramValue.getText())));
        deleteParam.addActionListener(e -> nodeModel.deleteParameter(paramTable.getSelectedRow()));

        quiet.onChoose(connectionKind, connectionModel::chooseKind);
        quiet.onChoose(dataEnd, connectionModel::chooseData);
        quiet.onChoose(relationEnd, connectionModel::chooseRelation);
        addConnection.addActionListener(e -> show(connectionModel.add(), "connection added"));
        deleteConnection.addActionListener(e -> show(connectionModel.delete(connectionList.getSelectedIndex()),
                "connection deleted"));
    }

    private ParameterType chosenType() {
        String t = (String) paramType.getSelectedItem();
        return t == null || UNTYPED.equals(t) ? null : ParameterType.fromAttribute(t);
    }

    private void showParameter(String refusal) {
        status.setText(refusal == null ? "parameter set; Save/Update the node to keep it" : "Refused: " + refusal);
    }

    /** Renames the loaded node to the "Rename to" name; a name the module uses opens the Merge/Replace dialog. */
    private void rename() {
        if (nodeModel.loaded() == null) {
            return;
        }
        String target = newName.getText().strip();
        EditResult r = MergeReplaceDialog.renameOrAsk(this, editor, nodeModel.loaded(), target);
        if (r == null) {
            status.setText("rename cancelled");
            return;
        }
        show(r, "renamed to " + target);
        if (r.accepted()) {
            newName.setText("");
            nodeName.setText(target);
        }
    }

    private void show(EditResult r, String done) {
        status.setText(r.accepted() ? done : "Refused: " + r.reason());
    }
}
