package org.fdnet.hi.layout;

import java.awt.geom.Point2D;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Function;
import org.eclipse.elk.graph.ElkNode;
import org.eclipse.elk.graph.util.ElkGraphUtil;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * A large network laid out module by module: each module's nodes, with the connections inside it, by ELK on
 * its own (the modules side by side on the machine's cores), then the modules as blocks, by ELK again, in the
 * direction values flow between them. Every node keeps its place inside its module's block; connections across
 * modules are drawn from block to block.
 */
final class ModuleBlockLayout {
    /** Blocks stand further apart than nodes, so the lines between them show which module they join. */
    private static final double BLOCK_SPREAD = 2.5;
    private static final double MARGIN = 20;

    private ModuleBlockLayout() {
    }

    static Map<NodeRef, Point2D> positions(NetworkInfo network, Function<NodeRef, NodeSize> sizes) {
        List<ModuleInfo> modules = network.modules().stream().filter(m -> !m.nodes().isEmpty()).toList();
        Map<String, List<ConnectionInfo>> inside = new HashMap<>();
        for (ConnectionInfo c : ElkLayeredLayout.allConnections(network)) {
            if (c.data().module().equals(c.relation().module())) {
                inside.computeIfAbsent(c.data().module(), m -> new ArrayList<>()).add(c);
            }
        }
        Map<String, Map<NodeRef, ElkNode>> laidOut = layOutModules(modules, inside, sizes);
        ElkNode top = ElkLayeredLayout.graph(BLOCK_SPREAD);
        Map<String, ElkNode> blocks = new LinkedHashMap<>();
        laidOut.forEach((module, nodes) -> blocks.put(module, block(top, nodes)));
        Set<String> joined = new HashSet<>();
        for (ConnectionInfo c : ElkLayeredLayout.allConnections(network)) {
            boolean reader = c.kind() == ConnectionKind.READER;
            ElkNode from = blocks.get(reader ? c.data().module() : c.relation().module());
            ElkNode to = blocks.get(reader ? c.relation().module() : c.data().module());
            if (from != null && to != null && from != to
                    && joined.add(c.data().module() + '\n' + c.relation().module() + '\n' + reader)) {
                ElkGraphUtil.createSimpleEdge(from, to);
            }
        }
        ElkLayeredLayout.run(top);
        Map<NodeRef, Point2D> result = new LinkedHashMap<>();
        laidOut.forEach((module, nodes) -> {
            ElkNode block = blocks.get(module);
            nodes.forEach((ref, node) -> result.put(ref, new Point2D.Double(
                    block.getX() + node.getX() + MARGIN, block.getY() + node.getY() + MARGIN)));
        });
        return result;
    }

    /** Each module laid out on its own, as many at once as there are cores. */
    private static Map<String, Map<NodeRef, ElkNode>> layOutModules(List<ModuleInfo> modules,
            Map<String, List<ConnectionInfo>> inside, Function<NodeRef, NodeSize> sizes) {
        AtomicInteger threads = new AtomicInteger();
        ExecutorService pool = Executors.newFixedThreadPool(
                Math.max(1, Math.min(modules.size(), Runtime.getRuntime().availableProcessors())), r -> {
                    Thread t = new Thread(r, "layout-" + threads.incrementAndGet());
                    t.setDaemon(true);
                    return t;
                });
        try {
            Map<String, Future<Map<NodeRef, ElkNode>>> parts = new LinkedHashMap<>();
            for (ModuleInfo m : modules) {
                List<ConnectionInfo> connections = inside.getOrDefault(m.name(), List.of());
                parts.put(m.name(), pool.submit(() -> ElkLayeredLayout.layOut(
                        ElkLayeredLayout.nodesOf(m), connections, sizes, 1)));
            }
            Map<String, Map<NodeRef, ElkNode>> laidOut = new LinkedHashMap<>();
            for (Map.Entry<String, Future<Map<NodeRef, ElkNode>>> part : parts.entrySet()) {
                laidOut.put(part.getKey(), await(part.getKey(), part.getValue()));
            }
            return laidOut;
        } finally {
            pool.shutdownNow();
        }
    }

    private static Map<NodeRef, ElkNode> await(String module, Future<Map<NodeRef, ElkNode>> part) {
        try {
            return part.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while laying out module " + module, e);
        } catch (ExecutionException e) {
            throw new IllegalStateException("ELK could not lay out module " + module + ": " + e.getCause(), e.getCause());
        }
    }

    /** A block in {@code top} as large as the module's drawing. */
    private static ElkNode block(ElkNode top, Map<NodeRef, ElkNode> nodes) {
        double width = 0;
        double height = 0;
        for (ElkNode n : nodes.values()) {
            width = Math.max(width, n.getX() + n.getWidth());
            height = Math.max(height, n.getY() + n.getHeight());
        }
        ElkNode block = ElkGraphUtil.createNode(top);
        block.setDimensions(width, height);
        return block;
    }
}
