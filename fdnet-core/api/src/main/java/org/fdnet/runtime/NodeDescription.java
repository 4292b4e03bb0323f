package org.fdnet.runtime;

import java.util.List;
import org.fdnet.netinfo.LinkedConnection;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * What {@link Reflect} tells about a node: its definition, whether it runs here, its value (a Data) or
 * state (a Relation), and its declared connections.
 *
 * @param id          the id its events carry, or -1 if it never ran here
 * @param running     whether the node is in the running network on this host
 * @param value       a running Data's value, else {@code null}
 * @param state       a running Relation's state, else {@code null}
 * @param connections every declared connection touching it, with the module declaring each
 */
public record NodeDescription(NodeRef ref, NodeInfo info, int id, boolean running, Value value,
                              RelationState state, List<LinkedConnection> connections) {
    public NodeKind kind() {
        return info.kind();
    }

    public String className() {
        return info.className();
    }

    public String host() {
        return info.host();
    }
}
