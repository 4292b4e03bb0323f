package org.fdnet.hi.text;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import org.fdnet.hi.edit.NetworkEditor;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.speedy.SpeedyDesign;
import org.fdnet.hi.speedy.Updatable;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkChangeListener;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * The logic of the Advanced Module frame's connection tab: a connection is made by choosing, never typing,
 * its Data and its Relation among the nodes that exist (thesis §IX: "only existing Nodes will be selectable"),
 * so a connection to nothing cannot be declared.
 *
 * <pre>
 *   network (root) ─▶ choices (existing Datas, Relations; this module's connections)
 *   choices + selection (root) ─▶ actions (Add enabled, why not)
 * </pre>
 *
 * Choices are written as {@link NetworkInfo#referenceText}: a bare name for this module's and main's nodes,
 * {@code Module/Node} for the others.
 */
public final class ConnectionFormModel {
    private final NetworkEditor editor;
    private String module;
    private final SpeedyDesign speedy;
    private final NetworkChangeListener listener;

    private final Updatable network = Updatable.marker();
    private final Updatable choices = this::computeChoices;
    private final Updatable selection = Updatable.marker();
    private final Updatable actions = Updatable.marker();

    private final List<String> datas = new ArrayList<>();
    private final List<String> relations = new ArrayList<>();
    private final List<ConnectionInfo> connections = new ArrayList<>();
    private ConnectionKind kind = ConnectionKind.READER;
    private String data;
    private String relation;

    public ConnectionFormModel(NetworkEditor editor, String module, SpeedyDesign speedy) {
        this.editor = Objects.requireNonNull(editor, "editor");
        this.module = Objects.requireNonNull(module, "module");
        this.speedy = speedy;
        speedy.register("connection:network", network);
        speedy.register("connection:choices", choices, network);
        speedy.register("connection:selection", selection);
        speedy.register("connection:actions", actions, choices, selection);
        listener = change -> {
            this.module = ModuleRenames.follow(this.module, change);
            speedy.changed(network);
        };
        editor.network().addListener(listener);
        computeChoices();
    }

    public void detach() {
        editor.network().removeListener(listener);
    }

    /** The component the two node lists and the connection table depend on. */
    public Updatable choices() {
        return choices;
    }

    /** The component the Add button depends on. */
    public Updatable actions() {
        return actions;
    }

    public void chooseKind(ConnectionKind k) {
        kind = Objects.requireNonNull(k);
        speedy.changed(selection);
    }

    /** Chooses the Data end by its text in {@link #dataChoices()}; anything else clears the choice. */
    public void chooseData(String text) {
        data = text;
        speedy.changed(selection);
    }

    public void chooseRelation(String text) {
        relation = text;
        speedy.changed(selection);
    }

    /** Every Data of the network, as this module names it. */
    public List<String> dataChoices() {
        return List.copyOf(datas);
    }

    public List<String> relationChoices() {
        return List.copyOf(relations);
    }

    /** The connections this module declares. */
    public List<ConnectionInfo> connections() {
        return List.copyOf(connections);
    }

    public ConnectionKind kind() {
        return kind;
    }

    /** The chosen Data if it is one of the choices, else null. */
    public String data() {
        return data != null && datas.contains(data) ? data : null;
    }

    public String relation() {
        return relation != null && relations.contains(relation) ? relation : null;
    }

    /** Why Add cannot run now, or null. */
    public String whyNotAdd() {
        if (editor.network().module(module) == null) {
            return "module '" + module + "' no longer exists";
        }
        if (data() == null) {
            return datas.isEmpty() ? "the network has no Data to connect yet" : "choose an existing Data";
        }
        if (relation() == null) {
            return relations.isEmpty() ? "the network has no Relation to connect yet" : "choose an existing Relation";
        }
        return null;
    }

    public EditResult add() {
        String why = whyNotAdd();
        if (why != null) {
            return EditResult.refused(why);
        }
        NetworkInfo net = editor.network();
        NodeRef d = net.resolve(module, data());
        NodeRef r = net.resolve(module, relation());
        ConnectionInfo c = kind == ConnectionKind.READER ? ConnectionInfo.reader(d, r) : ConnectionInfo.writer(r, d);
        return editor.addConnection(module, c);
    }

    /** Deletes the {@code index}-th connection of {@link #connections()}. */
    public EditResult delete(int index) {
        if (index < 0 || index >= connections.size()) {
            return EditResult.refused("choose the connection to delete in the table first");
        }
        return editor.deleteConnection(module, connections.get(index));
    }

    /** How the table shows a connection: its kind and its ends as this module names them. */
    public String describe(ConnectionInfo c) {
        NetworkInfo net = editor.network();
        String d = net.referenceText(module, c.data());
        String r = net.referenceText(module, c.relation());
        return c.kind() == ConnectionKind.READER ? "Reader " + d + " → " + r : "Writer " + r + " → " + d;
    }

    private void computeChoices() {
        datas.clear();
        relations.clear();
        connections.clear();
        NetworkInfo net = editor.network();
        ModuleInfo own = net.module(module);
        if (own == null) {
            return;
        }
        List<ModuleInfo> order = new ArrayList<>();
        order.add(own);
        for (ModuleInfo m : net.modules()) {
            if (m != own) {
                order.add(m);
            }
        }
        for (ModuleInfo m : order) {
            for (NodeInfo n : m.nodes()) {
                String text = net.referenceText(module, new NodeRef(m.name(), n.name()));
                (n.kind() == NodeKind.DATA ? datas : relations).add(text);
            }
        }
        connections.addAll(own.connections());
    }
}
