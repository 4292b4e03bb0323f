package org.fdnet.netinfo;

import java.util.Objects;

/**
 * A Reader or Writer joining one Data and one Relation. Immutable; both ends are fully qualified.
 *
 * @param kind           Reader or Writer
 * @param name           the optional connection name of the file, or {@code null}
 * @param data           the Data end
 * @param relation       the Relation end
 * @param exists         the {@code exist} flag: {@code false} declares a connection that is not made
 *                       when the network starts (a Relation may activate it later through Paste)
 * @param dataInline     the file declared the Data inside this connection ({@code dstructure} in
 *                       {@code read}); kept so that saving an unmodified file keeps its shape
 * @param relationInline the same for the Relation ({@code pstructure} in {@code read})
 */
public record ConnectionInfo(ConnectionKind kind, String name, NodeRef data, NodeRef relation,
                             boolean exists, boolean dataInline, boolean relationInline) {
    /**
     * Checks the parts.
     *
     * @param kind           Reader or Writer
     * @param name           the connection name, or null
     * @param data           the Data end
     * @param relation       the Relation end
     * @param exists         false for a connection not made at start
     * @param dataInline     whether the file declared the Data inside a {@code read}
     * @param relationInline whether the file declared the Relation inside a {@code read}
     * @throws NullPointerException     when {@code kind}, {@code data} or {@code relation} is null
     * @throws IllegalArgumentException when a Writer claims an inline end (only {@code read} can declare them)
     */
    public ConnectionInfo {
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(data, "data");
        Objects.requireNonNull(relation, "relation");
        if (kind == ConnectionKind.WRITER && (dataInline || relationInline)) {
            throw new IllegalArgumentException("a Writer cannot declare its nodes inline");
        }
    }

    /**
     * An unnamed, active Reader: {@code relation} reads {@code data}.
     *
     * @param data     the Data read
     * @param relation the Relation that reads it
     * @return a Reader that exists at start, with no inline ends
     */
    public static ConnectionInfo reader(NodeRef data, NodeRef relation) {
        return new ConnectionInfo(ConnectionKind.READER, null, data, relation, true, false, false);
    }

    /**
     * An unnamed, active Writer: {@code relation} writes {@code data}.
     *
     * @param relation the Relation that writes
     * @param data     the Data it writes
     * @return a Writer that exists at start
     */
    public static ConnectionInfo writer(NodeRef relation, NodeRef data) {
        return new ConnectionInfo(ConnectionKind.WRITER, null, data, relation, true, false, false);
    }

    /**
     * Whether one of the ends is {@code ref}.
     *
     * @param ref a node
     * @return true when {@code ref} is the Data or the Relation end
     */
    public boolean touches(NodeRef ref) {
        return data.equals(ref) || relation.equals(ref);
    }

    /**
     * The same connection with every end equal to {@code from} pointing at {@code to}; inline flags of moved ends drop.
     *
     * @param from the node that goes away
     * @param to   the node that takes its place
     * @return this connection when it does not touch {@code from}, else a new one
     */
    public ConnectionInfo redirect(NodeRef from, NodeRef to) {
        boolean dataMoves = data.equals(from);
        boolean relationMoves = relation.equals(from);
        if (!dataMoves && !relationMoves) {
            return this;
        }
        return new ConnectionInfo(kind, name, dataMoves ? to : data, relationMoves ? to : relation, exists,
                dataInline && !dataMoves, relationInline && !relationMoves);
    }

    /**
     * Same kind and same ends: two such connections say the same thing.
     *
     * @param other another connection
     * @return true when kind, Data and Relation are equal (name and flags are not compared)
     */
    public boolean sameLink(ConnectionInfo other) {
        return kind == other.kind && data.equals(other.data) && relation.equals(other.relation);
    }

    /**
     * Same link, name and exist flag: the connection means the same. Whether a file declared an end
     * inline is only the file's shape, so it does not count.
     *
     * @param other another connection
     * @return true when link, name and exist flag are equal
     */
    public boolean sameDeclaration(ConnectionInfo other) {
        return sameLink(other) && java.util.Objects.equals(name, other.name) && exists == other.exists;
    }

    @Override
    public String toString() {
        return kind == ConnectionKind.READER
                ? "Reader " + data + " -> " + relation
                : "Writer " + relation + " -> " + data;
    }
}
