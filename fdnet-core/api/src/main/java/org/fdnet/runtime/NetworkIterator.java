package org.fdnet.runtime;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import org.fdnet.netinfo.NodeRef;

/**
 * The thesis's Iterator servant: follows the network from a node, breadth first, along the way values
 * flow ({@link #downstream}) or against it ({@link #upstream}). Named {@code NetworkIterator} so it is not
 * mistaken for {@link java.util.Iterator}, which it yields. A snapshot: later edits do not disturb it.
 */
public final class NetworkIterator implements Iterable<NodeRef> {
    private final List<NodeRef> nodes;

    private NetworkIterator(List<NodeRef> nodes) {
        this.nodes = nodes;
    }

    static NetworkIterator downstream(ServantScope scope, NodeRef start) {
        return new NetworkIterator(scope.read(d -> new ArrayList<>(d.descendants(start))));
    }

    static NetworkIterator upstream(ServantScope scope, NodeRef start) {
        return new NetworkIterator(scope.read(d -> new ArrayList<>(d.ancestors(start))));
    }

    @Override
    public Iterator<NodeRef> iterator() {
        return nodes.iterator();
    }

    /**
     * The nodes in the order the iterator yields them.
     *
     * @return an unmodifiable list, nearest first; the start node is in it only when it lies on a loop
     */
    public List<NodeRef> toList() {
        return List.copyOf(nodes);
    }
}
