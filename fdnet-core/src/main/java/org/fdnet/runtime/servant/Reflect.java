package org.fdnet.runtime.servant;

import java.util.List;
import org.fdnet.netinfo.LinkedConnection;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.RelationState;
import org.fdnet.runtime.RuntimeNetwork;
import org.fdnet.runtime.Value;

/** The Reflect servant: describes one node (definition, running state, value, connections). */
public final class Reflect {
    private final RuntimeNetwork network;
    private final Controller controller;

    Reflect(RuntimeNetwork network, Controller controller) {
        this.network = network;
        this.controller = controller;
    }

    /** The node's description, or {@code null} when the network defines no such node. */
    public NodeDescription describe(NodeRef ref) {
        record Defined(NodeInfo info, List<LinkedConnection> connections) {
        }
        Defined defined = network.readDefinition(d -> d.node(ref) == null ? null
                : new Defined(d.node(ref), List.copyOf(d.connectionsOf(ref))));
        if (defined == null) {
            return null;
        }
        Value value = defined.info().kind() == NodeKind.DATA ? controller.value(ref) : null;
        RelationState state = defined.info().kind() == NodeKind.RELATION ? controller.relationState(ref) : null;
        return new NodeDescription(ref, defined.info(), controller.nodeId(ref), value != null || state != null, value,
                state, defined.connections());
    }
}
