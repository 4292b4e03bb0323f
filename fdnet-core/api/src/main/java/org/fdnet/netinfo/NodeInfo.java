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
    /**
     * Checks the parts and copies the parameters.
     *
     * @param kind       Data or Relation
     * @param name       the name in its module
     * @param host       the host it lives on
     * @param path       where its class is found, empty for the class path
     * @param className  its class
     * @param parameters its parameters, copied
     * @throws NullPointerException when a part other than the parameters' entries is null
     */
    public NodeInfo {
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(host, "host");
        Objects.requireNonNull(path, "path");
        Objects.requireNonNull(className, "className");
        parameters = List.copyOf(parameters);
    }

    /**
     * A Data on localhost whose class is found on the class path.
     *
     * @param name       the node's name in its module
     * @param className  the Data's class, e.g. {@code DoubleData} or a fully qualified name
     * @param parameters its parameters, in order
     * @return a Data definition on {@code localhost}, with an empty path
     */
    public static NodeInfo data(String name, String className, Parameter... parameters) {
        return new NodeInfo(NodeKind.DATA, name, "localhost", "", className, List.of(parameters));
    }

    /**
     * A Relation on localhost whose class is found on the class path.
     *
     * @param name       the node's name in its module
     * @param className  the Relation's class, e.g. {@code LowPass} or a fully qualified name
     * @param parameters its parameters, in order
     * @return a Relation definition on {@code localhost}, with an empty path
     */
    public static NodeInfo relation(String name, String className, Parameter... parameters) {
        return new NodeInfo(NodeKind.RELATION, name, "localhost", "", className, List.of(parameters));
    }

    /**
     * The same node under another name.
     *
     * @param newName the new name
     * @return a new definition
     */
    public NodeInfo withName(String newName) {
        return new NodeInfo(kind, newName, host, path, className, parameters);
    }

    /**
     * The same node on another host.
     *
     * @param newHost the host it is to live on
     * @return a new definition
     */
    public NodeInfo withHost(String newHost) {
        return new NodeInfo(kind, name, newHost, path, className, parameters);
    }

    /**
     * The same node with other parameters.
     *
     * @param newParameters every parameter it is to have, in order (copied)
     * @return a new definition
     */
    public NodeInfo withParameters(List<Parameter> newParameters) {
        return new NodeInfo(kind, name, host, path, className, newParameters);
    }

    /**
     * The value of the parameter called {@code parameterName}, or {@code null}.
     *
     * @param parameterName the parameter's name
     * @return the first such parameter's text as written, or null when the node has none of that name
     */
    public String parameter(String parameterName) {
        for (Parameter p : parameters) {
            if (parameterName.equals(p.name())) {
                return p.value();
            }
        }
        return null;
    }
}
