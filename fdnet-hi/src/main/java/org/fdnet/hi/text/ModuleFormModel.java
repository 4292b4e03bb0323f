package org.fdnet.hi.text;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import org.fdnet.hi.edit.NetworkEditor;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.speedy.SpeedyDesign;
import org.fdnet.hi.speedy.Updatable;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ModuleCounts;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkChangeListener;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * The logic of a module frame's top part and of the Basic Module frame: the module's name and load-at-start
 * flag (Save renames it and sets the flag), its nodes and connections by name and in numbers, and deleting
 * one of them. The module is followed when it is renamed elsewhere; when it is deleted, {@link #exists()}
 * turns false and the frame says so.
 *
 * <pre>
 *   network (root) ─▶ contents (names, kinds, connections, counts) ─┐
 *   typed name / load flag (root) ──────────────────────────────────┴▶ actions (Save enabled, why not)
 * </pre>
 */
public final class ModuleFormModel {
    private final NetworkEditor editor;
    private final SpeedyDesign speedy;
    private final NetworkChangeListener listener;
    private final Updatable network = Updatable.marker();
    private final Updatable contents = this::computeContents;
    private final Updatable typed = Updatable.marker();
    private final Updatable actions = Updatable.marker();

    private String module;
    private String typedName;
    private boolean typedLoadAtStart;
    private final List<NodeInfo> nodes = new ArrayList<>();
    private final List<ConnectionInfo> connections = new ArrayList<>();
    private ModuleCounts counts = new ModuleCounts(0, 0, 0, 0);
    private boolean loadAtStart;
    private boolean exists;

    public ModuleFormModel(NetworkEditor editor, String module, SpeedyDesign speedy) {
        this.editor = Objects.requireNonNull(editor, "editor");
        this.module = Objects.requireNonNull(module, "module");
        this.speedy = speedy;
        speedy.register("module:network", network);
        speedy.register("module:contents", contents, network);
        speedy.register("module:typed", typed);
        speedy.register("module:actions", actions, contents, typed);
        listener = change -> {
            String before = this.module;
            this.module = ModuleRenames.follow(before, change);
            if (!before.equals(this.module) && before.equals(typedName)) {
                typedName = this.module;
            }
            speedy.changed(network);
        };
        editor.network().addListener(listener);
        computeContents();
        typedName = module;
        typedLoadAtStart = loadAtStart;
    }

    public void detach() {
        editor.network().removeListener(listener);
    }

    public Updatable contents() {
        return contents;
    }

    public Updatable actions() {
        return actions;
    }

    /** The module's current name (it follows renames). */
    public String module() {
        return module;
    }

    public boolean exists() {
        return exists;
    }

    public boolean loadAtStart() {
        return loadAtStart;
    }

    public List<NodeInfo> nodes() {
        return List.copyOf(nodes);
    }

    public List<ConnectionInfo> connections() {
        return List.copyOf(connections);
    }

    public ModuleCounts counts() {
        return counts;
    }

    public void typeName(String text) {
        typedName = text.strip();
        speedy.changed(typed);
    }

    public void chooseLoadAtStart(boolean load) {
        typedLoadAtStart = load;
        speedy.changed(typed);
    }

    public String typedName() {
        return typedName;
    }

    public boolean typedLoadAtStart() {
        return typedLoadAtStart;
    }

    /** Why Save cannot run now, or null. */
    public String whyNotSave() {
        if (!exists) {
            return "module '" + module + "' no longer exists";
        }
        if (typedName.isEmpty()) {
            return "type the module's name";
        }
        if (typedName.equals(module) && typedLoadAtStart == loadAtStart) {
            return "nothing changed";
        }
        if (ModuleInfo.MAIN.equals(module) && !typedName.equals(module)) {
            return "module 'main' cannot be renamed";
        }
        if (ModuleInfo.MAIN.equals(module) && !typedLoadAtStart) {
            return "module 'main' is always loaded at start";
        }
        return null;
    }

    /** Renames the module and/or sets its load flag (two edits when both changed; the first refused stops). */
    public EditResult save() {
        String why = whyNotSave();
        if (why != null) {
            return EditResult.refused(why);
        }
        if (!typedName.equals(module)) {
            EditResult renamed = editor.renameModule(module, typedName);
            if (!renamed.accepted()) {
                return renamed;
            }
        }
        if (typedLoadAtStart != loadAtStart) {
            return editor.setLoadAtStart(module, typedLoadAtStart);
        }
        return EditResult.ok();
    }

    /** Deletes the module's node {@code nodeName} and every connection naming it. */
    public EditResult deleteNode(String nodeName) {
        return editor.deleteNode(new NodeRef(module, nodeName));
    }

    public EditResult deleteConnection(ConnectionInfo connection) {
        return editor.deleteConnection(module, connection);
    }

    private void computeContents() {
        nodes.clear();
        connections.clear();
        ModuleInfo m = editor.network().module(module);
        exists = m != null;
        if (m == null) {
            counts = new ModuleCounts(0, 0, 0, 0);
            return;
        }
        nodes.addAll(m.nodes());
        connections.addAll(m.connections());
        counts = editor.network().counts(module);
        loadAtStart = m.loadAtStart();
    }
}
