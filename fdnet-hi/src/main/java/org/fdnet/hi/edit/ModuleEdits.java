package org.fdnet.hi.edit;

import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.ModuleTree;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;

/** The module-level edits and their inverses. */
final class ModuleEdits {
    private ModuleEdits() {
    }

    static ReversibleEdit add(String module, boolean loadAtStart, int position) {
        return target -> {
            NetworkInfo network = target.network();
            int at = position < 0 ? network.modules().size() : position;
            network.addModule(module, loadAtStart, at);
            return delete(module);
        };
    }

    /**
     * Deletes a module with the modules inside it (the innermost first). Inverse: each back at its place, outermost
     * first, with its nodes, its connections, and other modules' connections to it.
     */
    static ReversibleEdit delete(String module) {
        return target -> {
            List<String> subtree = ModuleTree.subtree(target.network(), module);
            if (subtree.isEmpty()) {
                throw new EditRefusedException("the network has no module named '" + module + "'");
            }
            List<ReversibleEdit> restore = new ArrayList<>();
            for (int i = subtree.size() - 1; i >= 0; i--) {
                restore.add(0, deleteOne(subtree.get(i)).applyTo(target));
            }
            return CompositeEdit.of(restore);
        };
    }

    private static ReversibleEdit deleteOne(String module) {
        return target -> {
            NetworkInfo network = target.network();
            ModuleInfo doomed = network.module(module);
            if (doomed == null) {
                throw new EditRefusedException("the network has no module named '" + module + "'");
            }
            List<ReversibleEdit> restore = new ArrayList<>();
            restore.add(add(module, doomed.loadAtStart(), positionOf(network, module)));
            for (NodeInfo node : doomed.nodes()) {
                restore.add(NodeEdits.add(module, node, -1));
            }
            for (ConnectionInfo c : doomed.connections()) {
                restore.add(ConnectionEdits.add(module, c, -1));
            }
            for (ModuleInfo other : network.modules()) {
                List<ConnectionInfo> cs = other.connections();
                for (int i = 0; i < cs.size(); i++) {
                    ConnectionInfo c = cs.get(i);
                    if (!other.name().equals(module)
                            && (c.data().module().equals(module) || c.relation().module().equals(module))) {
                        restore.add(ConnectionEdits.add(other.name(), c, i));
                    }
                }
            }
            network.deleteModule(module);
            return CompositeEdit.of(restore);
        };
    }

    /** Renames a module; {@code to} is its new name or path (a nested module stays inside its parent). */
    static ReversibleEdit rename(String from, String to) {
        return target -> {
            String parent = ModuleTree.parentOf(from);
            String path = parent == null || to.indexOf('/') >= 0 ? to : parent + "/" + to;
            List<String> subtree = ModuleTree.subtree(target.network(), from);
            target.network().renameModule(from, path);
            for (String old : subtree) {
                target.moduleRenamed(old, path + old.substring(from.length()));
            }
            return rename(path, from);
        };
    }

    static ReversibleEdit loadAtStart(String module, boolean loadAtStart) {
        return target -> {
            ModuleInfo m = target.network().module(module);
            boolean was = m != null && m.loadAtStart();
            target.network().setLoadAtStart(module, loadAtStart);
            return loadAtStart(module, was);
        };
    }

    private static int positionOf(NetworkInfo network, String module) {
        int i = 0;
        for (ModuleInfo m : network.modules()) {
            if (m.name().equals(module)) {
                return i;
            }
            i++;
        }
        return i;
    }
}
