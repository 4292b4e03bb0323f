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
 * @param ref         the node's module and name
 * @param info        its definition: kind, class, host, parameters
 * @param id          the id its events carry, or -1 if it never ran here
 * @param running     whether the node is in the running network on this host
 * @param value       a running Data's value, else {@code null}
 * @param state       a running Relation's state, else {@code null}
 * @param connections every declared connection touching it, with the module declaring each
 */
public record NodeDescription(NodeRef ref, NodeInfo info, int id, boolean running, Value value,
                              RelationState state, List<LinkedConnection> connections) {
    /**
     * Whether the node is a Data or a Relation.
     *
     * @return the definition's kind
     */
    public NodeKind kind() {
        return info.kind();
    }

    /**
     * The class the node is an instance of.
     *
     * @return the class name as the definition gives it (a library class may be named without its package)
     */
    public String className() {
        return info.className();
    }

    /**
     * The host the node is declared on.
     *
     * @return the definition's {@code host}; empty when it names none (it then runs wherever the network runs)
     */
    public String host() {
        return info.host();
    }
}
