package org.fdnet.hi.layout;

import java.awt.geom.Point2D;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.layout.NodeLayout;
import org.fdnet.netinfo.LinkedConnection;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * Gives a place to every node the layout has none for, keeping the places the user set. A network with no
 * place at all (no .fdg) is laid out whole by ELK. Otherwise a new node connected to placed ones goes where
 * ELK would put it relative to them (ELK's position shifted by how far the user moved those neighbours
 * from ELK's); a new node with no placed neighbour goes in a row under the drawing.
 */
public final class AutoPlacement {
    private static final double GAP = 30;

    private AutoPlacement() {
    }

    /** @return how many nodes were placed */
    public static int place(NetworkInfo network, NetworkLayout layout, Function<NodeRef, NodeSize> sizes) {
        List<NodeRef> unplaced = new ArrayList<>();
        boolean anyPlaced = false;
        double bottom = 0;
        double left = Double.MAX_VALUE;
        for (ModuleInfo m : network.modules()) {
            for (NodeInfo n : m.nodes()) {
                NodeRef ref = new NodeRef(m.name(), n.name());
                NodeLayout at = layout.node(ref);
                if (at == null) {
                    unplaced.add(ref);
                } else {
                    anyPlaced = true;
                    double h = at.height() != null ? at.height() : sizes.apply(ref).height();
                    bottom = Math.max(bottom, at.y() + h);
                    left = Math.min(left, at.x());
                }
            }
        }
        if (unplaced.isEmpty()) {
            return 0;
        }
        if (!anyPlaced) {
            ElkLayeredLayout.positions(network, sizes).forEach((ref, p) -> layout.put(ref, NodeLayout.at(p.getX(), p.getY())));
            return unplaced.size();
        }
        List<NodeRef> loners = new ArrayList<>();
        List<NodeRef> connected = new ArrayList<>();
        for (NodeRef ref : unplaced) {
            (placedNeighbours(network, layout, ref).isEmpty() ? loners : connected).add(ref);
        }
        if (!connected.isEmpty()) {
            Map<NodeRef, Point2D> elk = ElkLayeredLayout.positions(network, sizes);
            for (NodeRef ref : connected) {
                double dx = 0;
                double dy = 0;
                List<NodeRef> neighbours = placedNeighbours(network, layout, ref);
                for (NodeRef n : neighbours) {
                    dx += layout.node(n).x() - elk.get(n).getX();
                    dy += layout.node(n).y() - elk.get(n).getY();
                }
                Point2D p = elk.get(ref);
                layout.put(ref, NodeLayout.at(p.getX() + dx / neighbours.size(), p.getY() + dy / neighbours.size()));
            }
        }
        double x = left == Double.MAX_VALUE ? 20 : left;
        for (NodeRef ref : loners) {
            layout.put(ref, NodeLayout.at(x, bottom + GAP));
            x += sizes.apply(ref).width() + GAP;
        }
        return unplaced.size();
    }

    private static List<NodeRef> placedNeighbours(NetworkInfo network, NetworkLayout layout, NodeRef ref) {
        List<NodeRef> result = new ArrayList<>();
        for (LinkedConnection c : network.connectionsOf(ref)) {
            NodeRef other = c.connection().data().equals(ref) ? c.connection().relation() : c.connection().data();
            if (layout.node(other) != null && !result.contains(other)) {
                result.add(other);
            }
        }
        return result;
    }
}
