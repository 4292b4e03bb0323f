package org.fdnet.hi.edit;

import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.MergePolicy;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * Replace and Merge (thesis Figures 28–29): two nodes become one. Both are undone the same way: the
 * connections of the node that stays are taken away, the node gets its own content back, the node that
 * went comes back at its place, and every connection either of them had returns to its place.
 */
final class NodePairEdits {
    private NodePairEdits() {
    }

    static ReversibleEdit replace(NodeRef replaced, NodeRef replacement) {
        return target -> {
            Before before = Before.of(target.network(), replaced, replacement);
            target.network().replaceNode(replaced, replacement);
            return before.undoing(target.network(), replaced, replacement);
        };
    }

    static ReversibleEdit merge(NodeRef first, NodeRef second, MergePolicy policy) {
        return target -> {
            Before before = Before.of(target.network(), first, second);
            target.network().mergeNodes(first, second, policy);
            return before.undoing(target.network(), first, second);
        };
    }

    /** The two nodes and their connections before the edit. */
    private record Before(NodeInfo kept, NodeInfo gone, int gonePosition, ConnectionPlaces connections) {
        static Before of(NetworkInfo network, NodeRef kept, NodeRef gone) {
            NodeInfo k = NodeEdits.require(network, kept);
            NodeInfo g = NodeEdits.require(network, gone);
            return new Before(k, g, NodeEdits.positionOf(network.module(gone.module()), gone.node()),
                    ConnectionPlaces.of(network, List.of(kept, gone)));
        }

        ReversibleEdit undoing(NetworkInfo after, NodeRef keptRef, NodeRef goneRef) {
            List<ReversibleEdit> undo = new ArrayList<>(ConnectionPlaces.of(after, List.of(keptRef)).removing());
            undo.add(NodeEdits.update(keptRef, kept));
            undo.add(NodeEdits.add(goneRef.module(), gone, gonePosition));
            undo.addAll(connections.restoring());
            return CompositeEdit.of(undo);
        }
    }
}
