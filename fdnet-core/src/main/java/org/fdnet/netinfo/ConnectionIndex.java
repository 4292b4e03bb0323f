package org.fdnet.netinfo;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Connections by node, across all modules, built in one pass over the network. NetworkInfo keeps one
 * and rebuilds it lazily after a change, so queries on a 20,000-connection network cost microseconds
 * while an edit costs nothing extra.
 */
final class ConnectionIndex {
    private final Map<NodeRef, List<LinkedConnection>> byNode = new HashMap<>();
    /** Where a value can flow next: Data to its readers, Relation to the Datas it writes. */
    private final Map<NodeRef, List<NodeRef>> downstream = new HashMap<>();
    private final Map<NodeRef, List<NodeRef>> upstream = new HashMap<>();

    ConnectionIndex(Iterable<ModuleInfo> modules) {
        for (ModuleInfo module : modules) {
            for (ConnectionInfo c : module.connections()) {
                add(module.name(), c);
            }
        }
    }

    void add(String module, ConnectionInfo c) {
        LinkedConnection linked = new LinkedConnection(module, c);
        byNode.computeIfAbsent(c.data(), k -> new ArrayList<>(4)).add(linked);
        byNode.computeIfAbsent(c.relation(), k -> new ArrayList<>(4)).add(linked);
        NodeRef from = c.kind() == ConnectionKind.READER ? c.data() : c.relation();
        NodeRef to = c.kind() == ConnectionKind.READER ? c.relation() : c.data();
        downstream.computeIfAbsent(from, k -> new ArrayList<>(4)).add(to);
        upstream.computeIfAbsent(to, k -> new ArrayList<>(4)).add(from);
    }

    List<LinkedConnection> connectionsOf(NodeRef ref) {
        return byNode.getOrDefault(ref, List.of());
    }

    List<NodeRef> next(NodeRef ref, boolean down) {
        return (down ? downstream : upstream).getOrDefault(ref, List.of());
    }
}
