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

    /**
     * Adds an empty module ({@link org.fdnet.netinfo.NetworkInfo#addModule}).
     *
     * @param module      the new module's name
     * @param loadAtStart whether it loads when the network starts
     * @return the edit; refused when the module exists
     */
    public static NetworkEdit addModule(String module, boolean loadAtStart) {
        return n -> n.addModule(module, loadAtStart);
    }

    /**
     * Deletes a module with its nodes and the connections touching them ({@link org.fdnet.netinfo.NetworkInfo#deleteModule}).
     *
     * @param module the module's name
     * @return the edit; refused for {@code main} or an unknown module
     */
    public static NetworkEdit deleteModule(String module) {
        return n -> n.deleteModule(module);
    }

    /**
     * Adds a node ({@link org.fdnet.netinfo.NetworkInfo#addNode}).
     *
     * @param module the module it goes into
     * @param node   the node's definition
     * @return the edit; refused when the name is taken in that module
     */
    public static NetworkEdit addNode(String module, NodeInfo node) {
        return n -> n.addNode(module, node);
    }

    /**
     * Replaces a node's definition ({@link org.fdnet.netinfo.NetworkInfo#updateNode}).
     *
     * @param ref  the node to replace
     * @param node its new definition
     * @return the edit; refused when there is no such node
     */
    public static NetworkEdit updateNode(NodeRef ref, NodeInfo node) {
        return n -> n.updateNode(ref, node);
    }

    /**
     * Deletes a node and every connection touching it ({@link org.fdnet.netinfo.NetworkInfo#deleteNode}).
     *
     * @param ref the node to delete
     * @return the edit; refused when there is no such node
     */
    public static NetworkEdit deleteNode(NodeRef ref) {
        return n -> n.deleteNode(ref);
    }

    /**
     * Adds a connection ({@link org.fdnet.netinfo.NetworkInfo#addConnection}).
     *
     * @param module     the module that declares it
     * @param connection the Reader or Writer
     * @return the edit; refused when an end does not exist or the connection is already there
     */
    public static NetworkEdit addConnection(String module, ConnectionInfo connection) {
        return n -> n.addConnection(module, connection);
    }

    /**
     * Deletes a connection ({@link org.fdnet.netinfo.NetworkInfo#deleteConnection}).
     *
     * @param module     the module that declares it
     * @param connection the Reader or Writer
     * @return the edit; refused when that module declares no such connection
     */
    public static NetworkEdit deleteConnection(String module, ConnectionInfo connection) {
        return n -> n.deleteConnection(module, connection);
    }

    /**
     * Sets one named parameter (keeping its declared type, if any), adding it when absent.
     *
     * @param ref   the node
     * @param name  the parameter's name
     * @param value its new text
     * @return the edit; refused when there is no such node or the text does not fit the parameter's declared type
     */
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

    /**
     * Several edits applied as one: all or nothing.
     *
     * @param edits the edits, applied in this order
     * @return one edit, refused when any of them is
     */
    public static NetworkEdit all(NetworkEdit... edits) {
        return n -> {
            for (NetworkEdit e : edits) {
                e.applyTo(n);
            }
        };
    }
}
