package org.fdnet.runtime;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Set;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.LinkedConnection;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * The LinkageIterator servant: follows the network from a node like {@link NetworkIterator}, but yields
 * the connections it crosses, each with whether it is live (both ends running, active).
 */
public final class LinkageIterator implements Iterable<LinkageIterator.Linkage> {
    /**
     * One connection crossed.
     *
     * @param module     the module that declares it
     * @param connection the Reader or Writer
     * @param live       whether both ends run and it is active
     */
    public record Linkage(String module, ConnectionInfo connection, boolean live) {
    }

    private final List<Linkage> linkages;

    private LinkageIterator(List<Linkage> linkages) {
        this.linkages = linkages;
    }

    static LinkageIterator downstream(ServantScope scope, NodeRef start) {
        WholeNetwork.Snapshot snapshot = scope.snapshot();
        NetworkInfo d = snapshot.definition();
        List<LinkedConnection> crossed = new ArrayList<>();
        Set<NodeRef> seen = new HashSet<>();
        ArrayDeque<NodeRef> queue = new ArrayDeque<>();
        queue.add(start);
        seen.add(start);
        while (!queue.isEmpty()) {
            NodeRef at = queue.poll();
            for (LinkedConnection lc : d.connectionsOf(at)) {
                ConnectionInfo c = lc.connection();
                NodeRef from = c.kind() == ConnectionKind.READER ? c.data() : c.relation();
                NodeRef to = c.kind() == ConnectionKind.READER ? c.relation() : c.data();
                if (from.equals(at)) {
                    crossed.add(lc);
                    if (seen.add(to)) {
                        queue.add(to);
                    }
                }
            }
        }
        List<Linkage> linkages = new ArrayList<>();
        for (LinkedConnection lc : crossed) {
            linkages.add(new Linkage(lc.module(), lc.connection(), scope.live(snapshot, lc)));
        }
        return new LinkageIterator(linkages);
    }

    @Override
    public Iterator<Linkage> iterator() {
        return linkages.iterator();
    }

    /**
     * The connections in the order the iterator yields them.
     *
     * @return an unmodifiable list, nearest first
     */
    public List<Linkage> toList() {
        return List.copyOf(linkages);
    }
}
