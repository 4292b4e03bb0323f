package org.fdnet.hi.edit;

import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.LinkedConnection;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;

/** Node edits and their inverses. */
final class NodeEdits {
    private NodeEdits() {
    }

    /** {@code position} -1: at the end of the module's nodes. */
    static ReversibleEdit add(String module, NodeInfo node, int position) {
        return target -> {
            NetworkInfo network = target.network();
            NodeRef ref = position < 0 ? network.addNode(module, node) : network.addNode(module, node, position);
            return delete(ref);
        };
    }

    /** Inverse: the node at its place, then each of its connections at its place in its module. */
    static ReversibleEdit delete(NodeRef ref) {
        return target -> {
            NetworkInfo network = target.network();
            NodeInfo node = require(network, ref);
            List<ReversibleEdit> restore = new ArrayList<>();
            restore.add(add(ref.module(), node, positionOf(network.module(ref.module()), ref.node())));
            restore.addAll(ConnectionPlaces.of(network, List.of(ref)).restoring());
            network.deleteNode(ref);
            return CompositeEdit.of(restore);
        };
    }

    static ReversibleEdit update(NodeRef ref, NodeInfo updated) {
        return target -> {
            NodeInfo before = require(target.network(), ref);
            target.network().updateNode(ref, updated);
            return update(ref, before);
        };
    }

    static ReversibleEdit rename(NodeRef ref, String newName) {
        return target -> {
            NodeRef renamed = target.network().renameNode(ref, newName);
            target.nodeRenamed(ref, renamed);
            return rename(renamed, ref.node());
        };
    }

    static NodeInfo require(NetworkInfo network, NodeRef ref) {
        NodeInfo node = network.node(ref);
        if (node == null) {
            throw new EditRefusedException("module '" + ref.module() + "' has no node named '" + ref.node() + "'");
        }
        return node;
    }

    static int positionOf(ModuleInfo module, String node) {
        int i = 0;
        for (NodeInfo n : module.nodes()) {
            if (n.name().equals(node)) {
                return i;
            }
            i++;
        }
        return i;
    }

    static boolean touchesAny(LinkedConnection c, List<NodeRef> refs) {
        return refs.stream().anyMatch(r -> c.connection().touches(r));
    }
}
