package org.fdnet.netinfo;

import java.util.Objects;

/**
 * A fully qualified node name: module and node. Written {@code Module/Node} in files and messages.
 * Names never contain '/', so the form is unambiguous.
 */
public record NodeRef(String module, String node) implements Comparable<NodeRef> {
    public NodeRef {
        Objects.requireNonNull(module, "module");
        Objects.requireNonNull(node, "node");
    }

    /** Parses {@code Module/Node}; a bare name is a node of {@code defaultModule}. */
    public static NodeRef parse(String text, String defaultModule) {
        int slash = text.indexOf('/');
        if (slash < 0) {
            return new NodeRef(defaultModule, text);
        }
        return new NodeRef(text.substring(0, slash), text.substring(slash + 1));
    }

    @Override
    public int compareTo(NodeRef other) {
        int byModule = module.compareTo(other.module);
        return byModule != 0 ? byModule : node.compareTo(other.node);
    }

    @Override
    public String toString() {
        return module + "/" + node;
    }
}
