package org.fdnet.hi.edit;

import java.nio.file.Path;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.MergePolicy;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkEdit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The editor's {@link NetworkEditor}: every call becomes a {@link ReversibleEdit} applied to the network,
 * whose inverse goes on the undo stack (inverse edits, never a copy of the whole model). A refusal changes
 * nothing, is returned as {@link EditResult#refused} and told to the {@link EditorListener}s (the status bar).
 * Swing thread only, like the NetworkInfo it edits.
 *
 * <p>With an {@link EditGate} set (live mode), every edit, undo and redo is first tried on a copy and the
 * result handed to the gate; only when the gate answers executed is it applied here. Changes that come from
 * elsewhere (the running network reshaping itself) enter through {@link #adopt}, outside the history.
 */
public final class UndoableNetworkEditor implements NetworkEditor {
    private static final Logger LOG = LoggerFactory.getLogger(UndoableNetworkEditor.class);

    private final EditTarget target;
    private final EditHistory history = new EditHistory();
    private final List<EditorListener> listeners = new CopyOnWriteArrayList<>();
    private EditGate gate;
    private volatile Path networkFile;

    public UndoableNetworkEditor(NetworkInfo network, NetworkLayout layout) {
        this.target = new EditTarget(Objects.requireNonNull(network), Objects.requireNonNull(layout));
    }

    @Override
    public NetworkInfo network() {
        return target.network();
    }

    @Override
    public Path networkFile() {
        return networkFile;
    }

    /** Where the network was read from or saved to ({@code null}: never saved). */
    public void setNetworkFile(Path file) {
        this.networkFile = file;
    }

    /** The view state edited alongside the network (renames carry positions and colours). */
    public NetworkLayout layout() {
        return target.layout();
    }

    /** Every later edit, undo and redo goes through {@code gate} first; {@code null}: edits apply at once. */
    public void setGate(EditGate gate) {
        this.gate = gate;
    }

    public EditGate gate() {
        return gate;
    }

    /**
     * Makes a change that happened elsewhere (the running network changed itself, or executed another tool's
     * edit): applied as is, not through the gate, not undoable, not marking the file unsaved. The change is tried
     * on a copy first, so one that does not fit changes nothing and throws {@link EditRefusedException}.
     */
    public void adopt(NetworkEdit change) {
        change.applyTo(network().copy());
        change.applyTo(network());
        fireHistory();
    }

    public void addEditorListener(EditorListener listener) {
        listeners.add(listener);
    }

    public void removeEditorListener(EditorListener listener) {
        listeners.remove(listener);
    }

    // ---------------------------------------------------------------- history

    public boolean canUndo() {
        return history.undoLabel() != null;
    }

    public boolean canRedo() {
        return history.redoLabel() != null;
    }

    /** What Undo would take back ("Delete node main/judge"), or {@code null}. */
    public String undoLabel() {
        return history.undoLabel();
    }

    public String redoLabel() {
        return history.redoLabel();
    }

    /** Whether the network differs from what was last saved (or loaded). */
    public boolean dirty() {
        return history.dirty();
    }

    public void markSaved() {
        history.markSaved();
        fireHistory();
    }

    public EditResult undo() {
        EditHistory.Step step = history.popUndo();
        if (step == null) {
            return refuse("nothing to undo");
        }
        try {
            history.pushRedo(new EditHistory.Step(step.id(), step.label(), gated("Undo " + step.label(), step.edit())));
        } catch (EditRefusedException | IllegalArgumentException e) {
            history.pushUndo(step);
            return refuse("cannot undo " + step.label() + ": " + e.getMessage());
        }
        fireHistory();
        return EditResult.ok();
    }

    public EditResult redo() {
        EditHistory.Step step = history.popRedo();
        if (step == null) {
            return refuse("nothing to redo");
        }
        try {
            history.pushUndo(new EditHistory.Step(step.id(), step.label(), gated("Redo " + step.label(), step.edit())));
        } catch (EditRefusedException | IllegalArgumentException e) {
            history.pushRedo(step);
            return refuse("cannot redo " + step.label() + ": " + e.getMessage());
        }
        fireHistory();
        return EditResult.ok();
    }

    // ---------------------------------------------------------------- edits

    @Override
    public EditResult renameNetwork(String newName) {
        if (newName != null && newName.equals(network().name())) {
            return EditResult.ok();
        }
        return apply("Rename network " + network().name(), NetworkEdits.rename(newName), null);
    }

    @Override
    public EditResult addModule(String module, boolean loadAtStart) {
        return apply("Add module " + module, ModuleEdits.add(module, loadAtStart, -1), null);
    }

    @Override
    public EditResult deleteModule(String module) {
        return apply("Delete module " + module, ModuleEdits.delete(module), null);
    }

    @Override
    public EditResult renameModule(String oldName, String newName) {
        return apply("Rename module " + oldName, ModuleEdits.rename(oldName, newName), null);
    }

    @Override
    public EditResult setLoadAtStart(String module, boolean loadAtStart) {
        return apply("Load at start of " + module, ModuleEdits.loadAtStart(module, loadAtStart), null);
    }

    @Override
    public EditResult addNode(String module, NodeInfo node) {
        return apply("Add node " + module + "/" + node.name(), NodeEdits.add(module, node, -1),
                new NodeRef(module, node.name()));
    }

    @Override
    public EditResult updateNode(NodeRef ref, NodeInfo updated) {
        if (updated.name().equals(ref.node())) {
            return apply("Update node " + ref, NodeEdits.update(ref, updated), ref);
        }
        NodeRef renamed = new NodeRef(ref.module(), updated.name());
        return apply("Update node " + ref, CompositeEdit.of(List.of(
                NodeEdits.rename(ref, updated.name()), NodeEdits.update(renamed, updated))), renamed);
    }

    @Override
    public EditResult setParameters(NodeRef ref, List<Parameter> parameters) {
        NodeInfo node = network().node(ref);
        if (node == null) {
            return refuse("module '" + ref.module() + "' has no node named '" + ref.node() + "'");
        }
        return apply("Parameters of " + ref, NodeEdits.update(ref, node.withParameters(parameters)), ref);
    }

    @Override
    public EditResult deleteNode(NodeRef ref) {
        return apply("Delete node " + ref, NodeEdits.delete(ref), null);
    }

    @Override
    public EditResult renameNode(NodeRef ref, String newName) {
        return apply("Rename node " + ref, NodeEdits.rename(ref, newName), new NodeRef(ref.module(), newName));
    }

    @Override
    public EditResult replaceNode(NodeRef replaced, NodeRef replacement) {
        return apply("Replace " + replaced + " by " + replacement, NodePairEdits.replace(replaced, replacement), replaced);
    }

    @Override
    public EditResult mergeNodes(NodeRef first, NodeRef second, MergePolicy policy) {
        return apply("Merge " + second + " into " + first, NodePairEdits.merge(first, second, policy), first);
    }

    @Override
    public EditResult addConnection(String module, ConnectionInfo connection) {
        return apply("Add " + connection, ConnectionEdits.add(module, connection, -1), null);
    }

    @Override
    public EditResult deleteConnection(String module, ConnectionInfo connection) {
        return apply("Delete " + connection, ConnectionEdits.delete(module, connection), null);
    }

    /**
     * Changes a Reader or Writer (its name, exist flag or ends) in place, as one step. Not on
     * {@link NetworkEditor}: only the graphic panel edits connections this way.
     */
    public EditResult updateConnection(String module, ConnectionInfo connection, ConnectionInfo updated) {
        return apply("Change " + connection, target -> {
            int position = network().module(module) == null ? -1 : network().module(module).connections().indexOf(connection);
            return CompositeEdit.of(List.of(ConnectionEdits.delete(module, connection),
                    ConnectionEdits.add(module, updated, position))).applyTo(target);
        }, null);
    }

    private EditResult apply(String label, ReversibleEdit edit, NodeRef produced) {
        ReversibleEdit inverse;
        try {
            inverse = gated(label, edit);
        } catch (EditRefusedException | IllegalArgumentException e) {
            return refuse(e.getMessage());
        }
        history.done(label, inverse);
        fireHistory();
        return produced == null ? EditResult.ok() : EditResult.ok(produced);
    }

    /**
     * Applies {@code edit} here, asking the gate first (when there is one) with the network the edit would
     * make; returns the inverse. Throws {@link EditRefusedException} with the gate's reason, changing nothing.
     */
    private ReversibleEdit gated(String label, ReversibleEdit edit) {
        if (gate != null) {
            EditTarget trial = new EditTarget(network().copy(), new NetworkLayout());
            edit.applyTo(trial);
            if (!trial.network().equals(network())) {
                ChangeOutcome outcome = gate.admit(label, network().copy(), trial.network());
                if (!outcome.executed()) {
                    throw new EditRefusedException("the running network refused it: " + outcome.reason());
                }
            }
        }
        return edit.applyTo(target);
    }

    private EditResult refuse(String reason) {
        LOG.debug("refused: {}", reason);
        for (EditorListener l : listeners) {
            l.refused(reason);
        }
        return EditResult.refused(reason);
    }

    private void fireHistory() {
        for (EditorListener l : listeners) {
            l.historyChanged();
        }
    }
}
