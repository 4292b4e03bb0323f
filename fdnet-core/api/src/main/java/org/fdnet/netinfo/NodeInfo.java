package org.fdnet.netinfo;

import java.util.List;
import java.util.Objects;

/**
 * A Data or Relation as the network definition declares it. Immutable: edits replace it.
 * A node knows nothing of its connections; the connections name the nodes they join.
 *
 * @param kind       Data or Relation
 * @param name       unique within its module; never contains '/'
 * @param host       the host the node lives on (a registered host name, or localhost)
 * @param path       where its class is found: empty for a built-in class, else a folder or jar
 * @param className  the node's implementation class
 * @param parameters in file order
 */
public record NodeInfo(NodeKind kind, String name, String host, String path, String className,
                       List<Parameter> parameters) {
    public NodeInfo {
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(host, "host");
        Objects.requireNonNull(path, "path");
        Objects.requireNonNull(className, "className");
        parameters = List.copyOf(parameters);
    }

    public static NodeInfo data(String name, String className, Parameter... parameters) {
        return new NodeInfo(NodeKind.DATA, name, "localhost", "", className, List.of(parameters));
    }

    public static NodeInfo relation(String name, String className, Parameter... parameters) {
        return new NodeInfo(NodeKind.RELATION, name, "localhost", "", className, List.of(parameters));
    }

    public NodeInfo withName(String newName) {
        return new NodeInfo(kind, newName, host, path, className, parameters);
    }

    public NodeInfo withHost(String newHost) {
        return new NodeInfo(kind, name, newHost, path, className, parameters);
    }

    public NodeInfo withParameters(List<Parameter> newParameters) {
        return new NodeInfo(kind, name, host, path, className, newParameters);
    }

    /** The value of the parameter called {@code parameterName}, or {@code null}. */
    public String parameter(String parameterName) {
        for (Parameter p : parameters) {
            if (parameterName.equals(p.name())) {
                return p.value();
            }
        }
        return null;
    }
}
