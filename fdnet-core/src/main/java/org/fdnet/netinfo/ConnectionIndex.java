package org.fdnet.netinfo;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Connections by node, across all modules, and where values flow from each node: one entry per
 * node, so a traversal step costs one hash lookup. NetworkInfo keeps one index, extends it in place
 * when a connection is added and drops it when connections are removed or re-pointed (it is rebuilt
 * in one pass on the next query).
 */
final class ConnectionIndex {
    private final Map<NodeRef, Entry> entries = new HashMap<>();

    private static final class Entry {
        final List<LinkedConnection> connections = new ArrayList<>(4);
        /** Data: the Relations reading it; Relation: the Datas it writes. */
        final List<NodeRef> downstream = new ArrayList<>(2);
        /** Data: the Relations writing it; Relation: the Datas it reads. */
        final List<NodeRef> upstream = new ArrayList<>(2);
    }

    ConnectionIndex(Iterable<ModuleInfo> modules) {
        for (ModuleInfo module : modules) {
            for (ConnectionInfo c : module.connections()) {
                add(module.name(), c);
            }
        }
    }

    void add(String module, ConnectionInfo c) {
        LinkedConnection linked = new LinkedConnection(module, c);
        Entry data = entries.computeIfAbsent(c.data(), k -> new Entry());
        Entry relation = entries.computeIfAbsent(c.relation(), k -> new Entry());
        data.connections.add(linked);
        relation.connections.add(linked);
        if (c.kind() == ConnectionKind.READER) {
            data.downstream.add(c.relation());
            relation.upstream.add(c.data());
        } else {
            relation.downstream.add(c.data());
            data.upstream.add(c.relation());
        }
    }

    List<LinkedConnection> connectionsOf(NodeRef ref) {
        Entry e = entries.get(ref);
        return e == null ? List.of() : e.connections;
    }

    /** Where a value can flow next from {@code ref} ({@code down}) or came from ({@code !down}). */
    List<NodeRef> next(NodeRef ref, boolean down) {
        Entry e = entries.get(ref);
        return e == null ? List.of() : down ? e.downstream : e.upstream;
    }
}
