package org.fdnet.hi.layout;

import java.awt.geom.Point2D;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.eclipse.elk.alg.layered.options.GreedySwitchType;
import org.eclipse.elk.alg.layered.options.LayeredMetaDataProvider;
import org.eclipse.elk.alg.layered.options.LayeredOptions;
import org.eclipse.elk.core.RecursiveGraphLayoutEngine;
import org.eclipse.elk.core.data.LayoutMetaDataService;
import org.eclipse.elk.core.options.CoreOptions;
import org.eclipse.elk.core.options.Direction;
import org.eclipse.elk.core.options.EdgeRouting;
import org.eclipse.elk.core.util.BasicProgressMonitor;
import org.eclipse.elk.graph.ElkNode;
import org.eclipse.elk.graph.util.ElkGraphUtil;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * The ELK layered call, values flowing left to right: every connection is an edge in the direction values
 * flow (Reader: Data to Relation; Writer: Relation to Data). A network of up to {@link #BY_MODULE_FROM} nodes is
 * laid out as one graph, where the flow across modules reads best; a larger one module by module
 * ({@link ModuleBlockLayout}), which keeps each module together and lays out 1,000 nodes in a fraction of the
 * time one graph takes (and 10,000 at all: one graph overflows ELK's stack there). Default node placement
 * (Brandes–Köpf): NETWORK_SIMPLEX overflows the stack at about 1,000 nodes (DESIGN.md).
 */
public final class ElkLayeredLayout {
    /** Networks with at least this many nodes are laid out module by module (property {@code fdnet.hi.layout.byModuleFrom}). */
    public static final int BY_MODULE_FROM = Integer.getInteger("fdnet.hi.layout.byModuleFrom", 300);
    private static final int THOROUGHNESS = Integer.getInteger("fdnet.hi.elk.thoroughness", 2);
    /** Space around a node, and between the layers values flow through. */
    private static final double NODE_SPACING = 24;
    private static final double LAYER_SPACING = 60;
    private static volatile boolean registered;

    private ElkLayeredLayout() {
    }

    /** Top-left corners, by node, for nodes of the given sizes. */
    public static Map<NodeRef, Point2D> positions(NetworkInfo network, Function<NodeRef, NodeSize> sizes) {
        if (byModule(network)) {
            return ModuleBlockLayout.positions(network, sizes);
        }
        List<NodeRef> all = network.modules().stream().flatMap(m -> nodesOf(m).stream()).toList();
        Map<NodeRef, Point2D> result = new LinkedHashMap<>();
        layOut(all, allConnections(network), sizes, 1).forEach((ref, node) ->
                result.put(ref, new Point2D.Double(node.getX() + 20, node.getY() + 20)));
        return result;
    }

    /** Whether {@link #positions} lays {@code network} out module by module (else as one graph). */
    public static boolean byModule(NetworkInfo network) {
        return nodeCount(network) >= BY_MODULE_FROM && network.modules().size() > 1;
    }

    /** Every node of every module. */
    public static int nodeCount(NetworkInfo network) {
        return network.modules().stream().mapToInt(m -> m.nodes().size()).sum();
    }

    /**
     * Lays out {@code nodes} and the connections among them (a connection to a node not given is left out);
     * {@code spread} multiplies the spacing.
     *
     * @return each node's ELK node, its place set (relative to the drawing's top-left corner)
     */
    static Map<NodeRef, ElkNode> layOut(Collection<NodeRef> nodes, Collection<ConnectionInfo> connections,
                                        Function<NodeRef, NodeSize> sizes, double spread) {
        ElkNode root = graph(spread);
        Map<NodeRef, ElkNode> placed = new LinkedHashMap<>();
        for (NodeRef ref : nodes) {
            ElkNode node = ElkGraphUtil.createNode(root);
            NodeSize size = sizes.apply(ref);
            node.setDimensions(size.width(), size.height());
            placed.put(ref, node);
        }
        for (ConnectionInfo c : connections) {
            ElkNode data = placed.get(c.data());
            ElkNode relation = placed.get(c.relation());
            if (data != null && relation != null) {
                if (c.kind() == ConnectionKind.READER) {
                    ElkGraphUtil.createSimpleEdge(data, relation);
                } else {
                    ElkGraphUtil.createSimpleEdge(relation, data);
                }
            }
        }
        run(root);
        return placed;
    }

    /** An empty graph with the editor's layered settings. */
    static ElkNode graph(double spread) {
        register();
        ElkNode root = ElkGraphUtil.createGraph();
        root.setProperty(CoreOptions.ALGORITHM, LayeredOptions.ALGORITHM_ID);
        root.setProperty(CoreOptions.DIRECTION, Direction.RIGHT);
        root.setProperty(LayeredOptions.SPACING_NODE_NODE, NODE_SPACING * spread);
        root.setProperty(LayeredOptions.SPACING_NODE_NODE_BETWEEN_LAYERS, LAYER_SPACING * spread);
        // The editor draws straight lines, so ELK need not route edges orthogonally; fewer crossing
        // minimisation passes keep a 300-node layout well under a second on a loaded machine.
        root.setProperty(LayeredOptions.EDGE_ROUTING, EdgeRouting.POLYLINE);
        root.setProperty(LayeredOptions.THOROUGHNESS, THOROUGHNESS);
        root.setProperty(LayeredOptions.CROSSING_MINIMIZATION_GREEDY_SWITCH_TYPE, GreedySwitchType.OFF);
        return root;
    }

    static void run(ElkNode root) {
        new RecursiveGraphLayoutEngine().layout(root, new BasicProgressMonitor());
    }

    static List<ConnectionInfo> allConnections(NetworkInfo network) {
        return network.modules().stream().flatMap(m -> m.connections().stream()).toList();
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

    /** The nodes of {@code module}, as references. */
    static List<NodeRef> nodesOf(ModuleInfo module) {
        return module.nodes().stream().map(n -> new NodeRef(module.name(), n.name())).toList();
    }
}
