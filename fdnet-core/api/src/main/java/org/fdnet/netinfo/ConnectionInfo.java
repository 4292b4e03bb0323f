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
    public ConnectionInfo {
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(data, "data");
        Objects.requireNonNull(relation, "relation");
        if (kind == ConnectionKind.WRITER && (dataInline || relationInline)) {
            throw new IllegalArgumentException("a Writer cannot declare its nodes inline");
        }
    }

    public static ConnectionInfo reader(NodeRef data, NodeRef relation) {
        return new ConnectionInfo(ConnectionKind.READER, null, data, relation, true, false, false);
    }

    public static ConnectionInfo writer(NodeRef relation, NodeRef data) {
        return new ConnectionInfo(ConnectionKind.WRITER, null, data, relation, true, false, false);
    }

    /** Whether one of the ends is {@code ref}. */
    public boolean touches(NodeRef ref) {
        return data.equals(ref) || relation.equals(ref);
    }

    /** The same connection with every end equal to {@code from} pointing at {@code to}; inline flags of moved ends drop. */
    public ConnectionInfo redirect(NodeRef from, NodeRef to) {
        boolean dataMoves = data.equals(from);
        boolean relationMoves = relation.equals(from);
        if (!dataMoves && !relationMoves) {
            return this;
        }
        return new ConnectionInfo(kind, name, dataMoves ? to : data, relationMoves ? to : relation, exists,
                dataInline && !dataMoves, relationInline && !relationMoves);
    }

    /** Same kind and same ends: two such connections say the same thing. */
    public boolean sameLink(ConnectionInfo other) {
        return kind == other.kind && data.equals(other.data) && relation.equals(other.relation);
    }

    /**
     * Same link, name and exist flag: the connection means the same. Whether a file declared an end
     * inline is only the file's shape, so it does not count.
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
