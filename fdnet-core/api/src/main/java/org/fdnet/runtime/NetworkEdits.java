package org.fdnet.runtime;

import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;

/** The common edits, ready to pass to {@link Controller#apply}. */
public final class NetworkEdits {
    private NetworkEdits() {
    }

    public static NetworkEdit addModule(String module, boolean loadAtStart) {
        return n -> n.addModule(module, loadAtStart);
    }

    public static NetworkEdit deleteModule(String module) {
        return n -> n.deleteModule(module);
    }

    public static NetworkEdit addNode(String module, NodeInfo node) {
        return n -> n.addNode(module, node);
    }

    public static NetworkEdit updateNode(NodeRef ref, NodeInfo node) {
        return n -> n.updateNode(ref, node);
    }

    public static NetworkEdit deleteNode(NodeRef ref) {
        return n -> n.deleteNode(ref);
    }

    public static NetworkEdit addConnection(String module, ConnectionInfo connection) {
        return n -> n.addConnection(module, connection);
    }

    public static NetworkEdit deleteConnection(String module, ConnectionInfo connection) {
        return n -> n.deleteConnection(module, connection);
    }

    /** Sets one named parameter (keeping its declared type, if any), adding it when absent. */
    public static NetworkEdit setParameter(NodeRef ref, String name, String value) {
        return n -> {
            NodeInfo node = n.node(ref);
            if (node == null) {
                throw new EditRefusedException("module '" + ref.module() + "' has no node named '" + ref.node() + "'");
            }
            List<Parameter> updated = new ArrayList<>();
            boolean found = false;
            for (Parameter p : node.parameters()) {
                if (name.equals(p.name())) {
                    updated.add(checked(ref, name, p, value));
                    found = true;
                } else {
                    updated.add(p);
                }
            }
            if (!found) {
                updated.add(Parameter.named(name, value));
            }
            n.setParameters(ref, updated);
        };
    }

    private static Parameter checked(NodeRef ref, String name, Parameter old, String value) {
        try {
            return new Parameter(name, old.type(), value);
        } catch (IllegalArgumentException e) {
            throw new EditRefusedException(ref + ": parameter '" + name + "': " + e.getMessage());
        }
    }

    /** Several edits applied as one: all or nothing. */
    public static NetworkEdit all(NetworkEdit... edits) {
        return n -> {
            for (NetworkEdit e : edits) {
                e.applyTo(n);
            }
        };
    }
}
