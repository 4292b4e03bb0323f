package org.fdnet.runtime;

import org.fdnet.netinfo.NodeRef;

/** The Reflect servant: describes one node (definition, running state, value, connections). */
public final class Reflect {
    private final ServantScope scope;

    Reflect(ServantScope scope) {
        this.scope = scope;
    }

    /**
     * The node's description, or {@code null} when the network defines no such node.
     *
     * @param ref the node's module and name
     * @return its description now, or null when the network defines no such node
     */
    public NodeDescription describe(NodeRef ref) {
        return scope.describe(ref);
    }
}
