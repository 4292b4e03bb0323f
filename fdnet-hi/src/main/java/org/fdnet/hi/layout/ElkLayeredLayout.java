package org.fdnet.hi.layout;

import java.awt.geom.Point2D;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Function;
import org.eclipse.elk.alg.layered.options.LayeredMetaDataProvider;
import org.eclipse.elk.alg.layered.options.GreedySwitchType;
import org.eclipse.elk.alg.layered.options.LayeredOptions;
import org.eclipse.elk.core.options.EdgeRouting;
import org.eclipse.elk.core.RecursiveGraphLayoutEngine;
import org.eclipse.elk.core.data.LayoutMetaDataService;
import org.eclipse.elk.core.options.CoreOptions;
import org.eclipse.elk.core.options.Direction;
import org.eclipse.elk.core.util.BasicProgressMonitor;
import org.eclipse.elk.graph.ElkNode;
import org.eclipse.elk.graph.util.ElkGraphUtil;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * The ELK layered call: every node of the network, every connection as an edge in the direction values
 * flow (Reader: Data to Relation; Writer: Relation to Data), laid out left to right. Default node
 * placement (Brandes–Köpf): NETWORK_SIMPLEX overflows the stack at about 1,000 nodes (DESIGN.md).
 */
public final class ElkLayeredLayout {
    private static final int THOROUGHNESS = Integer.getInteger("fdnet.hi.elk.thoroughness", 2);
    private static volatile boolean registered;

    private ElkLayeredLayout() {
    }

    /** Top-left corners, by node, for nodes of the given sizes. */
    public static Map<NodeRef, Point2D> positions(NetworkInfo network, Function<NodeRef, NodeSize> sizes) {
        register();
        ElkNode root = ElkGraphUtil.createGraph();
        root.setProperty(CoreOptions.ALGORITHM, LayeredOptions.ALGORITHM_ID);
        root.setProperty(CoreOptions.DIRECTION, Direction.RIGHT);
        root.setProperty(LayeredOptions.SPACING_NODE_NODE, 24.0);
        root.setProperty(LayeredOptions.SPACING_NODE_NODE_BETWEEN_LAYERS, 60.0);
        // The editor draws straight lines, so ELK need not route edges orthogonally; fewer crossing
        // minimisation passes keep a 1,000-node layout around a second on a loaded machine.
        root.setProperty(LayeredOptions.EDGE_ROUTING, EdgeRouting.POLYLINE);
        root.setProperty(LayeredOptions.THOROUGHNESS, THOROUGHNESS);
        root.setProperty(LayeredOptions.CROSSING_MINIMIZATION_GREEDY_SWITCH_TYPE, GreedySwitchType.OFF);
        Map<NodeRef, ElkNode> nodes = new LinkedHashMap<>();
        for (ModuleInfo m : network.modules()) {
            for (NodeInfo n : m.nodes()) {
                NodeRef ref = new NodeRef(m.name(), n.name());
                ElkNode node = ElkGraphUtil.createNode(root);
                NodeSize size = sizes.apply(ref);
                node.setDimensions(size.width(), size.height());
                nodes.put(ref, node);
            }
        }
        for (ModuleInfo m : network.modules()) {
            for (ConnectionInfo c : m.connections()) {
                ElkNode data = nodes.get(c.data());
                ElkNode relation = nodes.get(c.relation());
                if (data != null && relation != null) {
                    if (c.kind() == ConnectionKind.READER) {
                        ElkGraphUtil.createSimpleEdge(data, relation);
                    } else {
                        ElkGraphUtil.createSimpleEdge(relation, data);
                    }
                }
            }
        }
        new RecursiveGraphLayoutEngine().layout(root, new BasicProgressMonitor());
        Map<NodeRef, Point2D> result = new HashMap<>();
        nodes.forEach((ref, node) -> result.put(ref, new Point2D.Double(node.getX() + 20, node.getY() + 20)));
        return result;
    }

    private static void register() {
        if (!registered) {
            synchronized (ElkLayeredLayout.class) {
                if (!registered) {
                    LayoutMetaDataService.getInstance().registerLayoutMetaDataProviders(new LayeredMetaDataProvider());
                    registered = true;
                }
            }
        }
    }
}
