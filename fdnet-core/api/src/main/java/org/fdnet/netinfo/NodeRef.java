package org.fdnet.netinfo;

import java.util.Objects;

/**
 * A fully qualified node name: module and node. Written {@code Module/Node} in files and messages; a node of a
 * nested module is written with the module's path, {@code Arm/Hand/Node}. Node and module names never contain
 * '/', so the last '/' separates the module's path from the node's name.
 *
 * @param module the module's full name, e.g. {@code main} or {@code Arm/Hand}
 * @param node   the node's name in that module
 */
public record NodeRef(String module, String node) implements Comparable<NodeRef> {
    /**
     * Checks the parts.
     *
     * @param module the module's full name
     * @param node   the node's name in it
     * @throws NullPointerException when {@code module} or {@code node} is null
     */
    public NodeRef {
        Objects.requireNonNull(module, "module");
        Objects.requireNonNull(node, "node");
    }

    /**
     * Parses {@code Module/Node} (or {@code A/B/Node}); a bare name is a node of {@code defaultModule}.
     *
     * @param text          the reference as written
     * @param defaultModule the module of a bare name
     * @return the reference; whether the node exists is not checked
     */
    public static NodeRef parse(String text, String defaultModule) {
        int slash = text.lastIndexOf('/');
        if (slash < 0) {
            return new NodeRef(defaultModule, text);
        }
        return new NodeRef(text.substring(0, slash), text.substring(slash + 1));
    }

    /**
     * Written out because NodeRef is the key of every index: a record's generated equals/hashCode go
     * through method handles, which are slow until the JIT has compiled them (cold CLI runs).
     */
    @Override
    public boolean equals(Object o) {
        return this == o || o instanceof NodeRef other && node.equals(other.node) && module.equals(other.module);
    }

    @Override
    public int hashCode() {
        return module.hashCode() * 31 + node.hashCode();
    }

    @Override
    public int compareTo(NodeRef other) {
        int byModule = module.compareTo(other.module);
        return byModule != 0 ? byModule : node.compareTo(other.node);
    }

    /**
     * The node as messages name it: {@code module 'M', node 'N'}.
     *
     * @return the spelled-out name
     */
    public String spelledOut() {
        return "module '" + module + "', node '" + node + "'";
    }

    @Override
    public String toString() {
        return module + "/" + node;
    }
}
