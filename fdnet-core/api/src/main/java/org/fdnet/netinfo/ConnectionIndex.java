package org.fdnet.netinfo;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Connections by node, across all modules, and the graph of where values flow: one entry per node,
 * linked directly to the entries its values flow to and come from, so that ancestors/descendants walk
 * objects instead of hashing names (a query over a 10,000-node network costs about a millisecond, and
 * little more on a cold JVM). NetworkInfo keeps one index, extends it in place when a connection is
 * added and drops it when connections are removed or re-pointed; it is rebuilt on the next query.
 * Not thread-safe, like NetworkInfo itself: traversals mark entries with a per-query stamp.
 */
final class ConnectionIndex {
    private final Map<NodeRef, Entry> entries = new HashMap<>();
    private int stamp;

    private static final class Entry {
        final NodeRef ref;
        final List<LinkedConnection> connections = new ArrayList<>(4);
        /** Data: the Relations reading it; Relation: the Datas it writes. */
        final List<Entry> downstream = new ArrayList<>(2);
        /** Data: the Relations writing it; Relation: the Datas it reads. */
        final List<Entry> upstream = new ArrayList<>(2);
        int seen;

        Entry(NodeRef ref) {
            this.ref = ref;
        }
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
        Entry data = entries.computeIfAbsent(c.data(), Entry::new);
        Entry relation = entries.computeIfAbsent(c.relation(), Entry::new);
        data.connections.add(linked);
        relation.connections.add(linked);
        if (c.kind() == ConnectionKind.READER) {
            data.downstream.add(relation);
            relation.upstream.add(data);
        } else {
            relation.downstream.add(data);
            data.upstream.add(relation);
        }
    }

    List<LinkedConnection> connectionsOf(NodeRef ref) {
        Entry e = entries.get(ref);
        return e == null ? List.of() : e.connections;
    }

    /**
     * Every node reachable from {@code start} along the flow ({@code down}) or against it, breadth
     * first. The start node is included only when a loop leads back to it.
     */
    Set<NodeRef> reach(NodeRef start, boolean down) {
        Entry first = entries.get(start);
        if (first == null) {
            return new LinkedHashSet<>();
        }
        int mark = ++stamp;
        List<NodeRef> found = new ArrayList<>();
        ArrayDeque<Entry> queue = new ArrayDeque<>();
        queue.add(first);
        while (!queue.isEmpty()) {
            Entry e = queue.poll();
            List<Entry> next = down ? e.downstream : e.upstream;
            for (int i = 0, n = next.size(); i < n; i++) {
                Entry candidate = next.get(i);
                if (candidate.seen != mark) {
                    candidate.seen = mark;
                    found.add(candidate.ref);
                    queue.add(candidate);
                }
            }
        }
        return new LinkedHashSet<>(found);
    }
}
