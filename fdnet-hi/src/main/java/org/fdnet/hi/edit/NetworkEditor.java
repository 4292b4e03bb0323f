package org.fdnet.hi.edit;

import java.nio.file.Path;
import java.util.List;

import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.MergePolicy;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;

/**
 * The one door through which every view of the editor (the graphic panel, the text-based frames, dialogs)
 * changes the network being edited. Each call is one undoable step; a refused edit changes nothing and
 * returns {@link EditResult#refused}, whose reason the caller shows (the status bar shows it too).
 *
 * <p>Views read the network through {@link #network()} and learn of changes through its
 * {@link NetworkInfo#addListener change listeners}; they never edit the {@link NetworkInfo} directly, so that
 * undo, redo, the dirty marker and (in live mode) the running network all see every edit.
 */
public interface NetworkEditor {

    /** The network being edited; read it, never edit it directly. */
    NetworkInfo network();

    /**
     * The file the network was read from or last saved to, {@code null} for a network never saved: node paths are
     * relative to its folder, and node classes may be loaded only from under it.
     */
    default Path networkFile() {
        return null;
    }

    /** Gives the network a new name (saved in the .fdn's {@code cnet name} and the .fdg). */
    EditResult renameNetwork(String newName);

    EditResult addModule(String module, boolean loadAtStart);

    EditResult deleteModule(String module);

    EditResult renameModule(String oldName, String newName);

    EditResult setLoadAtStart(String module, boolean loadAtStart);

    EditResult addNode(String module, NodeInfo node);

    /** Replaces a node's host, path, class and parameters (and its name, when {@code updated} names it anew). */
    EditResult updateNode(NodeRef ref, NodeInfo updated);

    EditResult setParameters(NodeRef ref, List<Parameter> parameters);

    /** Deletes the node and every connection that names it, as one step. */
    EditResult deleteNode(NodeRef ref);

    EditResult renameNode(NodeRef ref, String newName);

    /** Thesis Figure 29: {@code replacement} takes {@code replaced}'s place in every connection. */
    EditResult replaceNode(NodeRef replaced, NodeRef replacement);

    /** Thesis Figure 28: the two nodes become one, keeping parameters as {@code policy} says. */
    EditResult mergeNodes(NodeRef first, NodeRef second, MergePolicy policy);

    EditResult addConnection(String module, ConnectionInfo connection);

    EditResult deleteConnection(String module, ConnectionInfo connection);

    /** The outcome of one edit: the node it produced where there is one, or the reason it was refused. */
    record EditResult(boolean accepted, NodeRef node, String reason) {
        public static EditResult ok() {
            return new EditResult(true, null, null);
        }

        public static EditResult ok(NodeRef node) {
            return new EditResult(true, node, null);
        }

        public static EditResult refused(String reason) {
            return new EditResult(false, null, reason);
        }
    }
}
