package org.fdnet.netinfo;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * A namespace of nodes and the connections it declares. Read-only to the outside: every change goes
 * through {@link NetworkInfo}, which keeps the whole network coherent and tells its listeners.
 * Nodes and connections keep the order in which they were declared.
 */
public final class ModuleInfo {
    /** The module of the top-level nodes; always present and always loaded at start. */
    public static final String MAIN = "main";

    private final String name;
    private final boolean loadAtStart;
    private final LinkedHashMap<String, NodeInfo> nodes = new LinkedHashMap<>();
    private final List<ConnectionInfo> connections = new ArrayList<>();

    ModuleInfo(String name, boolean loadAtStart) {
        this.name = name;
        this.loadAtStart = loadAtStart;
    }

    /** A module of another name or load flag, holding the same nodes and connections. */
    ModuleInfo with(String newName, boolean newLoadAtStart) {
        ModuleInfo copy = new ModuleInfo(newName, newLoadAtStart);
        copy.nodes.putAll(nodes);
        copy.connections.addAll(connections);
        return copy;
    }

    /**
     * The module's path: its own name, below its parents' ({@code Arm/Hand}); a top-level module's is its name.
     *
     * @return the full name
     */
    public String name() {
        return name;
    }

    /**
     * The last part of the path: the name the file gives the module.
     *
     * @return the module's own name, e.g. {@code Hand} for {@code Arm/Hand}
     */
    public String localName() {
        return name.substring(name.lastIndexOf('/') + 1);
    }

    /**
     * The enclosing module's path, or {@code null} for a top-level module (and {@code main}).
     *
     * @return the parent's full name, or null
     */
    public String parentName() {
        return ModuleTree.parentOf(name);
    }

    /**
     * Whether this is {@code main}, the module of the top-level nodes.
     *
     * @return true for {@code main}
     */
    public boolean isMain() {
        return MAIN.equals(name);
    }

    /**
     * Whether the module is loaded when the network starts; {@code main} always is. For a nested module: whether it
     * is loaded with its parent (so at start only when its parent is too, see {@link ModuleTree#atStart}).
     *
     * @return the {@code loadatstart} flag, true for {@code main}
     */
    public boolean loadAtStart() {
        return loadAtStart || isMain();
    }

    /**
     * The module's own nodes (not those of modules inside it), in declaration order.
     *
     * @return an unmodifiable live view
     */
    public Collection<NodeInfo> nodes() {
        return Collections.unmodifiableCollection(nodes.values());
    }

    /**
     * The node called {@code nodeName} in this module.
     *
     * @param nodeName the node's name, without the module
     * @return its definition, or null when the module has none of that name
     */
    public NodeInfo node(String nodeName) {
        return nodes.get(nodeName);
    }

    /**
     * Whether this module has a node called {@code nodeName}.
     *
     * @param nodeName the node's name, without the module
     * @return true when {@link #node} would find it
     */
    public boolean hasNode(String nodeName) {
        return nodes.containsKey(nodeName);
    }

    /**
     * The connections this module declares, in declaration order; their ends may lie in other modules.
     *
     * @return an unmodifiable live view
     */
    public List<ConnectionInfo> connections() {
        return Collections.unmodifiableList(connections);
    }

    /**
     * The connections this module declares that touch {@code ref} (see {@link NetworkInfo#connectionsOf} for all).
     *
     * @param ref a node of any module
     * @return a new list, in declaration order
     */
    public List<ConnectionInfo> connectionsOf(NodeRef ref) {
        List<ConnectionInfo> result = new ArrayList<>();
        for (ConnectionInfo c : connections) {
            if (c.touches(ref)) {
                result.add(c);
            }
        }
        return result;
    }

    /**
     * This module in numbers: its own nodes and the connections it declares.
     *
     * @return its Datas, Relations, Readers and Writers
     */
    public ModuleCounts counts() {
        int datas = 0;
        for (NodeInfo n : nodes.values()) {
            if (n.kind() == NodeKind.DATA) {
                datas++;
            }
        }
        int readers = 0;
        for (ConnectionInfo c : connections) {
            if (c.kind() == ConnectionKind.READER) {
                readers++;
            }
        }
        return new ModuleCounts(datas, nodes.size() - datas, readers, connections.size() - readers);
    }

    // ---- mutation, for NetworkInfo only ----

    void putNode(NodeInfo node) {
        nodes.put(node.name(), node);
    }

    void insertNode(int position, NodeInfo node) {
        LinkedHashMap<String, NodeInfo> reordered = new LinkedHashMap<>();
        int i = 0;
        for (Map.Entry<String, NodeInfo> e : nodes.entrySet()) {
            if (i++ == position) {
                reordered.put(node.name(), node);
            }
            reordered.put(e.getKey(), e.getValue());
        }
        reordered.putIfAbsent(node.name(), node);
        nodes.clear();
        nodes.putAll(reordered);
    }

    /** Replaces the node called {@code oldName} keeping its position in the declaration order. */
    void replaceNodeInPlace(String oldName, NodeInfo node) {
        if (oldName.equals(node.name())) {
            nodes.put(oldName, node);
            return;
        }
        LinkedHashMap<String, NodeInfo> reordered = new LinkedHashMap<>();
        for (Map.Entry<String, NodeInfo> e : nodes.entrySet()) {
            if (e.getKey().equals(oldName)) {
                reordered.put(node.name(), node);
            } else if (!e.getKey().equals(node.name())) {
                reordered.put(e.getKey(), e.getValue());
            }
        }
        nodes.clear();
        nodes.putAll(reordered);
    }

    void removeNode(String nodeName) {
        nodes.remove(nodeName);
    }

    void addConnection(ConnectionInfo connection) {
        connections.add(connection);
    }

    List<ConnectionInfo> mutableConnections() {
        return connections;
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof ModuleInfo other)) {
            return false;
        }
        return name.equals(other.name) && loadAtStart() == other.loadAtStart()
                && new ArrayList<>(nodes.values()).equals(new ArrayList<>(other.nodes.values()))
                && sameDeclarations(connections, other.connections);
    }

    private static boolean sameDeclarations(List<ConnectionInfo> a, List<ConnectionInfo> b) {
        if (a.size() != b.size()) {
            return false;
        }
        for (int i = 0; i < a.size(); i++) {
            if (!a.get(i).sameDeclaration(b.get(i))) {
                return false;
            }
        }
        return true;
    }

    @Override
    public int hashCode() {
        return Objects.hash(name, loadAtStart(), connections.size(), nodes.size());
    }

    @Override
    public String toString() {
        return "module " + name + " " + counts();
    }
}
