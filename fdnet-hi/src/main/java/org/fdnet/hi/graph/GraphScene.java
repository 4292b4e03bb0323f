package org.fdnet.hi.graph;

import java.awt.Color;
import java.awt.geom.Line2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import org.fdnet.hi.edit.UndoableNetworkEditor;
import org.fdnet.hi.layout.AutoPlacement;
import org.fdnet.hi.layout.NodeSize;
import org.fdnet.layout.ModuleLayout;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.layout.NodeLayout;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.ModuleTree;
import org.fdnet.netinfo.NetworkChange;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * What the graphic panel shows, apart from how: where each node is and how big (the .fdg layout), which
 * modules are visible, the selection and the highlighted ancestors/descendants. It listens to the network
 * so a node added by any view gets a place (automatic layout) and a deleted one leaves the selection.
 * Moving, colouring, sizing and hiding change only the layout (the .fdg), never the network.
 */
public final class GraphScene {
    /** Which relatives of a node to highlight. */
    public enum Relatives { ANCESTORS, DESCENDANTS, BOTH }

    private static final double PARALLEL_GAP = 5;

    private final UndoableNetworkEditor editor;
    private final List<SceneListener> listeners = new CopyOnWriteArrayList<>();
    /** Counts every change to what is drawn; {@link #stillRevision} counts all of them but moves of the selection. */
    private long revision;
    private long stillRevision;
    private final Set<NodeRef> selected = new LinkedHashSet<>();
    private ConnectionRef selectedConnection;
    private final Set<NodeRef> highlighted = new LinkedHashSet<>();
    private NodeRef highlightRoot;
    private boolean layoutChanged;
    private Map<NodeRef, String> liveValues = Map.of();

    public GraphScene(UndoableNetworkEditor editor) {
        this.editor = editor;
        AutoPlacement.place(editor.network(), editor.layout(), this::defaultSize);
        editor.network().addListener(this::networkChanged);
    }

    public NetworkInfo network() {
        return editor.network();
    }

    public NetworkLayout layout() {
        return editor.layout();
    }

    public void addListener(SceneListener l) {
        listeners.add(l);
    }

    // ---------------------------------------------------------------- geometry

    public Rectangle2D bounds(NodeRef ref) {
        NodeLayout at = layout().node(ref);
        NodeInfo node = network().node(ref);
        if (at == null || node == null) {
            return null;
        }
        NodeSize size = defaultSize(ref);
        return new Rectangle2D.Double(at.x(), at.y(), at.width() != null ? at.width() : size.width(),
                at.height() != null ? at.height() : size.height());
    }

    NodeSize defaultSize(NodeRef ref) {
        NodeInfo node = network().node(ref);
        return new NodeSize(NodeShapes.defaultWidth(ref.node(), node.kind()), NodeShapes.DEFAULT_HEIGHT);
    }

    public boolean visible(String module) {
        ModuleLayout m = layout().module(module);
        return m == null || m.visible();
    }

    /** The nodes of visible modules, in declaration order (later ones are drawn on top). */
    public List<NodeRef> visibleNodes() {
        List<NodeRef> refs = new ArrayList<>();
        for (ModuleInfo m : network().modules()) {
            if (visible(m.name())) {
                for (NodeInfo n : m.nodes()) {
                    refs.add(new NodeRef(m.name(), n.name()));
                }
            }
        }
        return refs;
    }

    /** Connections whose two ends are shown. */
    public List<ConnectionRef> visibleConnections() {
        List<ConnectionRef> result = new ArrayList<>();
        for (ModuleInfo m : network().modules()) {
            for (ConnectionInfo c : m.connections()) {
                if (visible(c.data().module()) && visible(c.relation().module())) {
                    result.add(new ConnectionRef(m.name(), c));
                }
            }
        }
        return result;
    }

    /** The segment a connection is drawn on, from the node values come from to the node they go to. */
    public Line2D segment(ConnectionInfo c) {
        boolean reader = c.kind() == org.fdnet.netinfo.ConnectionKind.READER;
        NodeRef from = reader ? c.data() : c.relation();
        NodeRef to = reader ? c.relation() : c.data();
        Rectangle2D a = bounds(from);
        Rectangle2D b = bounds(to);
        if (a == null || b == null) {
            return null;
        }
        Point2D ca = new Point2D.Double(a.getCenterX(), a.getCenterY());
        Point2D cb = new Point2D.Double(b.getCenterX(), b.getCenterY());
        Line2D line = new Line2D.Double(NodeShapes.border(network().node(from).kind(), a, cb),
                NodeShapes.border(network().node(to).kind(), b, ca));
        return hasOpposite(c) ? shifted(line, PARALLEL_GAP) : line;
    }

    /** A Relation that reads and writes the same Data (a feedback loop): its two arrows are drawn side by side. */
    private boolean hasOpposite(ConnectionInfo c) {
        for (var linked : network().connectionsOf(c.data())) {
            ConnectionInfo other = linked.connection();
            if (other.kind() != c.kind() && other.relation().equals(c.relation())) {
                return true;
            }
        }
        return false;
    }

    /** The line moved sideways (to its right, seen along its direction), so two opposite arrows do not overlap. */
    private static Line2D shifted(Line2D l, double by) {
        double dx = l.getX2() - l.getX1();
        double dy = l.getY2() - l.getY1();
        double d = Math.hypot(dx, dy);
        if (d == 0) {
            return l;
        }
        double ox = -dy / d * by;
        double oy = dx / d * by;
        return new Line2D.Double(l.getX1() + ox, l.getY1() + oy, l.getX2() + ox, l.getY2() + oy);
    }

    public NodeRef nodeAt(Point2D p) {
        List<NodeRef> nodes = visibleNodes();
        for (int i = nodes.size() - 1; i >= 0; i--) {
            Rectangle2D b = bounds(nodes.get(i));
            if (b != null && b.contains(p)) {
                return nodes.get(i);
            }
        }
        return null;
    }

    public ConnectionRef connectionAt(Point2D p, double tolerance) {
        ConnectionRef best = null;
        double bestDistance = tolerance;
        for (ConnectionRef c : visibleConnections()) {
            Line2D s = segment(c.connection());
            if (s != null) {
                double d = s.ptSegDist(p);
                if (d <= bestDistance) {
                    bestDistance = d;
                    best = c;
                }
            }
        }
        return best;
    }

    /** The box around every visible node, or an empty box at the origin. */
    public Rectangle2D extent() {
        Rectangle2D all = null;
        for (NodeRef ref : visibleNodes()) {
            Rectangle2D b = bounds(ref);
            if (b != null) {
                all = all == null ? (Rectangle2D) b.clone() : all.createUnion(b);
            }
        }
        return all == null ? new Rectangle2D.Double() : all;
    }

    // ---------------------------------------------------------------- colours

    public Color moduleColour(String module) {
        ModuleLayout m = layout().module(module);
        if (m != null && m.colour() != null) {
            return Color.decode(m.colour());
        }
        return ModulePalette.colourFor(moduleIndex(module));
    }

    /** The node's own colour, else a light tint of its module's. */
    public Color fillColour(NodeRef ref) {
        NodeLayout at = layout().node(ref);
        if (at != null && at.colour() != null) {
            return Color.decode(at.colour());
        }
        return ModulePalette.tint(moduleColour(ref.module()));
    }

    private int moduleIndex(String module) {
        int i = 0;
        for (ModuleInfo m : network().modules()) {
            if (m.name().equals(module)) {
                return i;
            }
            i++;
        }
        return i;
    }

    // ---------------------------------------------------------------- view edits (the .fdg only)

    public void setModuleVisible(String module, boolean visible) {
        layout().moduleOrNew(module).setVisible(visible);
        if (!visible) {
            selected.removeIf(r -> r.module().equals(module));
        }
        viewChanged();
    }

    /** A text that changes exactly when the modules, their visibility or their colours do: for panels that list them. */
    public String modulesKey() {
        StringBuilder key = new StringBuilder();
        for (ModuleInfo m : network().modules()) {
            key.append(m.name()).append(visible(m.name())).append(moduleColour(m.name())).append('|');
        }
        return key.toString();
    }

    /** Shows or hides {@code module} and every module nested inside it. */
    public void setModuleSubtreeVisible(String module, boolean visible) {
        for (String m : ModuleTree.subtree(network(), module)) {
            if (visible(m) != visible) {
                setModuleVisible(m, visible);
            }
        }
    }

    /** Display all ({@code true}) or Display none ({@code false}). */
    public void setAllModulesVisible(boolean visible) {
        for (ModuleInfo m : network().modules()) {
            if (visible(m.name()) != visible) {
                setModuleVisible(m.name(), visible);
            }
        }
    }

    public void setModuleColour(String module, Color colour) {
        layout().moduleOrNew(module).setColour(ModulePalette.hex(colour));
        viewChanged();
    }

    public void setNodeColour(NodeRef ref, Color colour) {
        Rectangle2D b = bounds(ref);
        NodeLayout at = layout().node(ref);
        layout().put(ref, new NodeLayout(b.getX(), b.getY(), at.width(), at.height(),
                colour == null ? null : ModulePalette.hex(colour)));
        viewChanged();
    }

    public void setNodeSize(NodeRef ref, double width, double height) {
        NodeLayout at = layout().node(ref);
        layout().put(ref, new NodeLayout(at.x(), at.y(), width, height, at.colour()));
        viewChanged();
    }

    /** Moves every selected node by ({@code dx}, {@code dy}). */
    public void moveSelected(double dx, double dy) {
        for (NodeRef ref : selected) {
            NodeLayout at = layout().node(ref);
            if (at != null) {
                layout().put(ref, new NodeLayout(at.x() + dx, at.y() + dy, at.width(), at.height(), at.colour()));
            }
        }
        layoutChanged = true;
        revision++;
        notifyScene();
    }

    /** The selected nodes stopped moving (the drag is over): everything is drawn whole again. */
    public void endMove() {
        if (revision != stillRevision) {
            fireScene();
        }
    }

    /** Counts every change to what is drawn. */
    public long revision() {
        return revision;
    }

    /**
     * The {@link #revision} of the last change other than a move of the selected nodes: while it stays, everything
     * but the selected nodes and their connections is drawn as it was (what a drag repaints on).
     */
    public long stillRevision() {
        return stillRevision;
    }

    /** Lays out every node anew with ELK, forgetting positions (sizes and colours stay). */
    public void relayoutAll() {
        Map<NodeRef, NodeLayout> kept = new HashMap<>();
        for (NodeRef ref : allNodes()) {
            NodeLayout at = layout().node(ref);
            if (at != null) {
                kept.put(ref, at);
                layout().moduleOrNew(ref.module()).remove(ref.node());
            }
        }
        AutoPlacement.place(network(), layout(), r -> {
            NodeLayout k = kept.get(r);
            NodeSize size = defaultSize(r);
            return k == null || k.width() == null || k.height() == null ? size : new NodeSize(k.width(), k.height());
        });
        for (Map.Entry<NodeRef, NodeLayout> e : kept.entrySet()) {
            NodeLayout now = layout().node(e.getKey());
            layout().put(e.getKey(), new NodeLayout(now.x(), now.y(), e.getValue().width(), e.getValue().height(),
                    e.getValue().colour()));
        }
        viewChanged();
    }

    public boolean layoutChanged() {
        return layoutChanged;
    }

    public void markLayoutSaved() {
        layoutChanged = false;
    }

    // ---------------------------------------------------------------- live values (live mode; never saved)

    /** The latest value of each running Data that has one, as drawn under its node; {@code null} if none. */
    public String liveValue(NodeRef ref) {
        return liveValues.get(ref);
    }

    /** Replaces the values of the Datas in {@code latest}, keeping the others'; only the canvas repaints. */
    public void showLiveValues(Map<NodeRef, String> latest) {
        Map<NodeRef, String> merged = new HashMap<>(liveValues);
        merged.putAll(latest);
        liveValues = merged;
        fireValues();
    }

    /** Drops the values of Datas outside {@code modules} (an unloaded module's Datas have none). */
    public void keepLiveValuesOf(Set<String> modules) {
        if (liveValues.keySet().stream().allMatch(r -> modules.contains(r.module()))) {
            return;
        }
        Map<NodeRef, String> kept = new HashMap<>(liveValues);
        kept.keySet().removeIf(r -> !modules.contains(r.module()));
        liveValues = kept;
        fireValues();
    }

    /** Detached: no live values any more. */
    public void clearLiveValues() {
        liveValues = Map.of();
        fireValues();
    }

    private void fireValues() {
        stillRevision = ++revision;
        for (SceneListener l : listeners) {
            l.valuesChanged();
        }
    }

    // ---------------------------------------------------------------- selection and highlight

    public Set<NodeRef> selection() {
        return Collections.unmodifiableSet(selected);
    }

    public ConnectionRef selectedConnection() {
        return selectedConnection;
    }

    public void select(Set<NodeRef> nodes) {
        selected.clear();
        selected.addAll(nodes);
        selectedConnection = null;
        fireSelection();
    }

    public void toggle(NodeRef ref) {
        if (!selected.remove(ref)) {
            selected.add(ref);
        }
        selectedConnection = null;
        fireSelection();
    }

    public void selectConnection(ConnectionRef c) {
        selected.clear();
        selectedConnection = c;
        fireSelection();
    }

    public void highlight(NodeRef root, Relatives which) {
        highlighted.clear();
        highlightRoot = root;
        if (root != null) {
            if (which != Relatives.DESCENDANTS) {
                highlighted.addAll(network().ancestors(root));
            }
            if (which != Relatives.ANCESTORS) {
                highlighted.addAll(network().descendants(root));
            }
            highlighted.add(root);
        }
        fireScene();
    }

    public Set<NodeRef> highlighted() {
        return Collections.unmodifiableSet(highlighted);
    }

    public NodeRef highlightRoot() {
        return highlightRoot;
    }

    // ---------------------------------------------------------------- internals

    private List<NodeRef> allNodes() {
        List<NodeRef> refs = new ArrayList<>();
        for (ModuleInfo m : network().modules()) {
            for (NodeInfo n : m.nodes()) {
                refs.add(new NodeRef(m.name(), n.name()));
            }
        }
        return refs;
    }

    private void networkChanged(NetworkChange change) {
        AutoPlacement.place(network(), layout(), this::defaultSize);
        boolean selectionLost = selected.removeIf(r -> network().node(r) == null);
        if (selectedConnection != null) {
            ModuleInfo m = network().module(selectedConnection.module());
            if (m == null || !m.connections().contains(selectedConnection.connection())) {
                selectedConnection = null;
                selectionLost = true;
            }
        }
        if (highlightRoot != null && network().node(highlightRoot) == null) {
            highlighted.clear();
            highlightRoot = null;
        }
        fireScene();
        if (selectionLost || change.kind() == NetworkChange.Kind.NODE_CHANGED) {
            fireSelection();
        }
    }

    private void viewChanged() {
        layoutChanged = true;
        fireScene();
    }

    private void fireScene() {
        stillRevision = ++revision;
        notifyScene();
    }

    private void notifyScene() {
        for (SceneListener l : listeners) {
            l.sceneChanged();
        }
    }

    private void fireSelection() {
        stillRevision = ++revision;
        for (SceneListener l : listeners) {
            l.selectionChanged();
        }
    }
}
