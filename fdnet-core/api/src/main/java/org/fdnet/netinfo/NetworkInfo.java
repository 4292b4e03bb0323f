package org.fdnet.netinfo;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The logical layer of a network definition (the thesis's "NetworkInfo"): modules, their nodes and
 * connections, every edit that keeps them coherent, and the queries the editor and the runtime ask.
 * It does no I/O: {@code org.fdnet.netinfo.xml} reads and writes it.
 *
 * <p>Every edit checks everything it needs <em>before</em> it changes anything, so a refused edit
 * ({@link EditRefusedException}) leaves the model untouched. Completed edits are told to the
 * {@link NetworkChangeListener}s. Not thread-safe: one thread (the editor's, or the runtime's
 * controller) owns a NetworkInfo at a time.
 */
public final class NetworkInfo {
    private static final Logger LOG = LoggerFactory.getLogger(NetworkInfo.class);

    private String name;
    private final LinkedHashMap<String, ModuleInfo> modules = new LinkedHashMap<>();
    private final List<NetworkChangeListener> listeners = new CopyOnWriteArrayList<>();
    private ConnectionIndex index;

    /**
     * An empty network with its {@code main} module.
     *
     * @param name the network's name, or null for none
     */
    public NetworkInfo(String name) {
        this.name = name;
        modules.put(ModuleInfo.MAIN, new ModuleInfo(ModuleInfo.MAIN, true));
    }

    /**
     * A deep copy without listeners (nodes and connections are immutable, so sharing them is safe).
     *
     * @return a new network equal to this one; editing either leaves the other as it is
     */
    public NetworkInfo copy() {
        NetworkInfo copy = new NetworkInfo(name);
        copy.modules.clear();
        for (ModuleInfo m : modules.values()) {
            copy.modules.put(m.name(), m.with(m.name(), m.loadAtStart()));
        }
        return copy;
    }

    // ---------------------------------------------------------------- reading

    /**
     * The network's name, or {@code null} when the file gives none.
     *
     * @return the name, or null
     */
    public String name() {
        return name;
    }

    /**
     * Every module, {@code main} included, in declaration order.
     *
     * @return an unmodifiable live view
     */
    public Collection<ModuleInfo> modules() {
        return Collections.unmodifiableCollection(modules.values());
    }

    /**
     * The module called {@code moduleName}.
     *
     * @param moduleName its full name, a path for a nested module ({@code Arm/Hand})
     * @return the module, or null when the network has none of that name
     */
    public ModuleInfo module(String moduleName) {
        return modules.get(moduleName);
    }

    /**
     * The module {@code main}, which every network has.
     *
     * @return the main module, never null
     */
    public ModuleInfo main() {
        return modules.get(ModuleInfo.MAIN);
    }

    /**
     * The node {@code ref} names.
     *
     * @param ref the node's module and name
     * @return its definition, or null when there is no such module or node
     */
    public NodeInfo node(NodeRef ref) {
        ModuleInfo m = modules.get(ref.module());
        return m == null ? null : m.node(ref.node());
    }

    /**
     * The node a connection in {@code contextModule} means by {@code reference}: {@code Module/Node}
     * (or {@code A/B/Node}) as written; a bare name is looked up in {@code contextModule}, then in each module
     * enclosing it, outwards, then in {@code main}.
     *
     * @param contextModule the module that declares the connection
     * @param reference     the node as the connection writes it: a bare name or a {@code Module/Node} path
     * @return the node's full name, or {@code null} when no such node exists
     */
    public NodeRef resolve(String contextModule, String reference) {
        if (reference.indexOf('/') >= 0) {
            NodeRef ref = NodeRef.parse(reference, contextModule);
            return node(ref) != null ? ref : null;
        }
        for (String module = contextModule; module != null; module = ModuleTree.parentOf(module)) {
            ModuleInfo own = modules.get(module);
            if (own != null && own.hasNode(reference)) {
                return new NodeRef(module, reference);
            }
        }
        return main().hasNode(reference) ? new NodeRef(ModuleInfo.MAIN, reference) : null;
    }

    /**
     * The shortest text that {@link #resolve} turns back into {@code ref} from {@code contextModule}.
     *
     * @param contextModule the module that declares the connection
     * @param ref           the node to name
     * @return the bare node name when that resolves to {@code ref}, else {@code Module/Node}
     */
    public String referenceText(String contextModule, NodeRef ref) {
        return ref.equals(resolve(contextModule, ref.node())) ? ref.node() : ref.toString();
    }

    /**
     * Every connection, in any module, that has {@code ref} at one of its ends.
     *
     * @param ref the node
     * @return an unmodifiable list, each with the module declaring it; empty for an unknown node
     */
    public List<LinkedConnection> connectionsOf(NodeRef ref) {
        return Collections.unmodifiableList(index().connectionsOf(ref));
    }

    /**
     * Every node a value of {@code ref} can flow to: for a Data, the Relations reading it, the Datas
     * those write, and so on; for a Relation, the Datas it writes, their readers, and so on. The
     * start node belongs to the result only if it lies on a feedback loop. Breadth-first order.
     *
     * @param ref the node to start from
     * @return a new set, nearest first
     * @throws EditRefusedException when the network has no such node
     */
    public Set<NodeRef> descendants(NodeRef ref) {
        return reach(ref, true);
    }

    /**
     * Every node whose value can flow into {@code ref}: the mirror image of {@link #descendants}.
     *
     * @param ref the node to start from
     * @return a new set, nearest first
     * @throws EditRefusedException when the network has no such node
     */
    public Set<NodeRef> ancestors(NodeRef ref) {
        return reach(ref, false);
    }

    private Set<NodeRef> reach(NodeRef start, boolean down) {
        requireNode(start);
        return index().reach(start, down);
    }

    /**
     * How many nodes and connections one module declares (not those of the modules inside it).
     *
     * @param moduleName the module's full name
     * @return its Datas, Relations, Readers and Writers
     * @throws EditRefusedException when the network has no such module
     */
    public ModuleCounts counts(String moduleName) {
        return requireModule(moduleName).counts();
    }

    /**
     * How many nodes and connections the whole network declares.
     *
     * @return the sum of every module's counts
     */
    public ModuleCounts totalCounts() {
        ModuleCounts total = new ModuleCounts(0, 0, 0, 0);
        for (ModuleInfo m : modules.values()) {
            total = total.plus(m.counts());
        }
        return total;
    }

    // ---------------------------------------------------------------- listeners

    /**
     * Tells {@code listener} of every completed edit from now on, on the editing thread.
     *
     * @param listener the listener, not null; an exception from it is logged and the edit stands
     */
    public void addListener(NetworkChangeListener listener) {
        listeners.add(Objects.requireNonNull(listener));
    }

    /**
     * Stops telling {@code listener}.
     *
     * @param listener a listener added before; any other is ignored
     */
    public void removeListener(NetworkChangeListener listener) {
        listeners.remove(listener);
    }

    // ---------------------------------------------------------------- network and modules

    /**
     * Renames the network.
     *
     * @param newName the new name, or null for none
     */
    public void setName(String newName) {
        name = newName;
        changed(NetworkChange.Kind.NETWORK_RENAMED, null, null);
    }

    /**
     * Adds an empty module; {@code moduleName} may be a path ({@code Arm/Hand}) below an existing module.
     *
     * @param moduleName  the new module's full name
     * @param loadAtStart whether it loads when the network starts
     * @return the new module, last in declaration order
     * @throws EditRefusedException when the name is malformed or taken, or its parent module does not exist
     */
    public ModuleInfo addModule(String moduleName, boolean loadAtStart) {
        checkNewModule(moduleName);
        ModuleInfo module = new ModuleInfo(moduleName, loadAtStart);
        modules.put(moduleName, module);
        changed(NetworkChange.Kind.MODULE_ADDED, moduleName, null);
        return module;
    }

    /**
     * Adds an empty module at {@code position} in the declaration order (0 = first): what undoing a
     * module's deletion needs to give back the network exactly as it was.
     *
     * @param moduleName  the new module's full name
     * @param loadAtStart whether it loads when the network starts
     * @param position    its place among the modules, 0 to the number of modules
     * @return the new module
     * @throws EditRefusedException when the name is malformed or taken, its parent does not exist, or
     *                              {@code position} is out of range
     */
    public ModuleInfo addModule(String moduleName, boolean loadAtStart, int position) {
        checkNewModule(moduleName);
        checkPosition(position, modules.size());
        ModuleInfo module = new ModuleInfo(moduleName, loadAtStart);
        LinkedHashMap<String, ModuleInfo> reordered = new LinkedHashMap<>();
        int i = 0;
        for (ModuleInfo m : modules.values()) {
            if (i++ == position) {
                reordered.put(moduleName, module);
            }
            reordered.put(m.name(), m);
        }
        reordered.putIfAbsent(moduleName, module);
        modules.clear();
        modules.putAll(reordered);
        changed(NetworkChange.Kind.MODULE_ADDED, moduleName, null);
        return module;
    }

    private void checkNewModule(String moduleName) {
        ModelRules.checkModulePath(moduleName);
        if (modules.containsKey(moduleName)) {
            throw new EditRefusedException("the network already has a module named '" + moduleName + "'");
        }
        String parent = ModuleTree.parentOf(moduleName);
        if (parent != null && !modules.containsKey(parent)) {
            throw new EditRefusedException("module '" + moduleName + "' would lie inside module '" + parent
                    + "', which the network does not have");
        }
    }

    /**
     * Deletes a module, the modules inside it, their nodes, and every connection in any module that touches one of
     * them.
     *
     * @param moduleName the module's full name
     * @throws EditRefusedException for {@code main} or a module the network does not have
     */
    public void deleteModule(String moduleName) {
        ModuleInfo doomed = requireModule(moduleName);
        if (doomed.isMain()) {
            throw new EditRefusedException("module 'main' holds the network's core and cannot be deleted");
        }
        modules.keySet().removeIf(m -> ModuleTree.within(m, moduleName));
        for (ModuleInfo m : modules.values()) {
            m.mutableConnections().removeIf(c -> ModuleTree.within(c.data().module(), moduleName)
                    || ModuleTree.within(c.relation().module(), moduleName));
        }
        changed(NetworkChange.Kind.MODULE_DELETED, moduleName, null);
    }

    /**
     * Renames a module; the modules inside it and connections anywhere that name their nodes follow. A nested
     * module's new name is a path with the same parent ({@code Arm/Hand} → {@code Arm/Grip}) or a plain name, which
     * keeps the parent: renaming does not move a module.
     *
     * @param oldName the module's full name
     * @param newName the new name: a plain name, or a full path with the same parent
     * @throws EditRefusedException for {@code main}, an unknown module, a malformed or taken name, or a new name
     *                              with another parent
     */
    public void renameModule(String oldName, String newName) {
        ModuleInfo module = requireModule(oldName);
        if (module.isMain()) {
            throw new EditRefusedException("module 'main' cannot be renamed");
        }
        String parent = ModuleTree.parentOf(oldName);
        if (parent != null && newName != null && newName.indexOf('/') < 0) {
            newName = parent + "/" + newName;
        }
        ModelRules.checkModulePath(newName);
        if (oldName.equals(newName)) {
            return;
        }
        if (!Objects.equals(parent, ModuleTree.parentOf(newName))) {
            throw new EditRefusedException("cannot rename module '" + oldName + "' to '" + newName
                    + "': renaming keeps a module where it is");
        }
        if (modules.containsKey(newName)) {
            throw new EditRefusedException("cannot rename module '" + oldName + "': the network already has a module named '" + newName + "'");
        }
        LinkedHashMap<String, ModuleInfo> reordered = new LinkedHashMap<>();
        for (ModuleInfo m : modules.values()) {
            ModuleInfo kept = ModuleTree.within(m.name(), oldName)
                    ? m.with(newName + m.name().substring(oldName.length()), m.loadAtStart()) : m;
            reordered.put(kept.name(), kept);
        }
        modules.clear();
        modules.putAll(reordered);
        String renamed = newName;
        for (ModuleInfo m : modules.values()) {
            m.mutableConnections().replaceAll(c -> new ConnectionInfo(c.kind(), c.name(),
                    moved(c.data(), oldName, renamed), moved(c.relation(), oldName, renamed),
                    c.exists(), c.dataInline(), c.relationInline()));
        }
        changed(NetworkChange.Kind.MODULE_RENAMED, renamed, oldName);
    }

    private static NodeRef moved(NodeRef ref, String oldModule, String newModule) {
        return ModuleTree.within(ref.module(), oldModule)
                ? new NodeRef(newModule + ref.module().substring(oldModule.length()), ref.node()) : ref;
    }

    /**
     * Sets whether a module loads when the network starts.
     *
     * @param moduleName  the module's full name
     * @param loadAtStart true to load it at start
     * @throws EditRefusedException for an unknown module, or false for {@code main}
     */
    public void setLoadAtStart(String moduleName, boolean loadAtStart) {
        ModuleInfo module = requireModule(moduleName);
        if (module.isMain() && !loadAtStart) {
            throw new EditRefusedException("module 'main' is always loaded at start");
        }
        modules.put(moduleName, module.with(moduleName, loadAtStart));
        changed(NetworkChange.Kind.MODULE_LOAD_AT_START_CHANGED, moduleName, null);
    }

    // ---------------------------------------------------------------- nodes

    /**
     * Adds a node, last among its module's nodes.
     *
     * @param moduleName the module's full name
     * @param node       the node's definition
     * @return the new node's module and name
     * @throws EditRefusedException for an unknown module, a malformed node, or a name the module already has
     */
    public NodeRef addNode(String moduleName, NodeInfo node) {
        ModuleInfo module = requireModule(moduleName);
        ModelRules.checkNode(node);
        if (module.hasNode(node.name())) {
            throw new EditRefusedException("module '" + moduleName + "' already has a node named '" + node.name()
                    + "' (replace or merge it instead)");
        }
        module.putNode(node);
        changed(NetworkChange.Kind.NODE_ADDED, moduleName, node.name());
        return new NodeRef(moduleName, node.name());
    }

    /**
     * Adds a node at {@code position} among its module's nodes (0 = first): what undoing a deletion needs.
     *
     * @param moduleName the module's full name
     * @param node       the node's definition
     * @param position   its place, 0 to the module's number of nodes
     * @return the new node's module and name
     * @throws EditRefusedException for an unknown module, a malformed node, a name the module already has, or
     *                              {@code position} out of range
     */
    public NodeRef addNode(String moduleName, NodeInfo node, int position) {
        ModuleInfo module = requireModule(moduleName);
        ModelRules.checkNode(node);
        if (module.hasNode(node.name())) {
            throw new EditRefusedException("module '" + moduleName + "' already has a node named '" + node.name()
                    + "' (replace or merge it instead)");
        }
        checkPosition(position, module.nodes().size());
        module.insertNode(position, node);
        changed(NetworkChange.Kind.NODE_ADDED, moduleName, node.name());
        return new NodeRef(moduleName, node.name());
    }

    /**
     * Changes a node's host, path, class or parameters. Its name and kind stay (rename, replace, merge for those).
     *
     * @param ref     the node
     * @param updated its new definition, with the same name (and the same kind while it is connected)
     * @throws EditRefusedException for an unknown node, a malformed definition, another name, or another kind of a
     *                              connected node
     */
    public void updateNode(NodeRef ref, NodeInfo updated) {
        NodeInfo current = requireNode(ref);
        ModelRules.checkNode(updated);
        if (!updated.name().equals(current.name())) {
            throw new EditRefusedException("updateNode keeps the name '" + current.name() + "'; use renameNode");
        }
        if (updated.kind() != current.kind()) {
            boolean connected = !connectionsOf(ref).isEmpty();
            if (connected) {
                throw new EditRefusedException(ref + " is connected: a " + current.kind().label()
                        + " cannot become a " + updated.kind().label() + " while connections need it as it is");
            }
        }
        modules.get(ref.module()).replaceNodeInPlace(ref.node(), updated);
        changed(NetworkChange.Kind.NODE_CHANGED, ref.module(), ref.node());
    }

    /**
     * Replaces a node's parameters, as {@link #updateNode} does.
     *
     * @param ref        the node
     * @param parameters every parameter it is to have, in order
     * @throws EditRefusedException for an unknown node or malformed parameters
     */
    public void setParameters(NodeRef ref, List<Parameter> parameters) {
        updateNode(ref, requireNode(ref).withParameters(parameters));
    }

    /**
     * Deletes a node and every connection, in any module, that touches it.
     *
     * @param ref the node
     * @throws EditRefusedException when the network has no such node
     */
    public void deleteNode(NodeRef ref) {
        requireNode(ref);
        removeConnectionsTouching(ref);
        modules.get(ref.module()).removeNode(ref.node());
        changed(NetworkChange.Kind.NODE_DELETED, ref.module(), ref.node());
    }

    /**
     * Renames a node in its module; its connections follow. A name already used is refused: replace or merge.
     *
     * @param ref     the node
     * @param newName its new name in the same module
     * @return the renamed node's module and name
     * @throws EditRefusedException for an unknown node, a malformed name, or a name the module already has
     */
    public NodeRef renameNode(NodeRef ref, String newName) {
        NodeInfo node = requireNode(ref);
        ModelRules.checkName("node", newName);
        NodeRef renamed = new NodeRef(ref.module(), newName);
        if (newName.equals(ref.node())) {
            return ref;
        }
        if (modules.get(ref.module()).hasNode(newName)) {
            throw new EditRefusedException("module '" + ref.module() + "' already has a node named '" + newName
                    + "': replace or merge the two nodes instead");
        }
        modules.get(ref.module()).replaceNodeInPlace(ref.node(), node.withName(newName));
        redirectConnections(ref, renamed);
        changed(NetworkChange.Kind.NODE_RENAMED, ref.module(), ref.node());
        return renamed;
    }

    /**
     * Replace Node (thesis Figure 28): {@code replaced} and all its connections go; {@code replacement}
     * takes its name and place and keeps only its own connections. Both live in the same module.
     *
     * @param replaced    the node that goes
     * @param replacement the node that takes its name and place
     * @return the resulting node, named as {@code replaced}
     * @throws EditRefusedException when either node is unknown, they are in different modules, or they are one node
     */
    public NodeRef replaceNode(NodeRef replaced, NodeRef replacement) {
        requireNode(replaced);
        NodeInfo replacing = requireNode(replacement);
        if (!replaced.module().equals(replacement.module())) {
            throw new EditRefusedException("replace works within one module: " + replaced + " and " + replacement + " are in different modules");
        }
        if (replaced.equals(replacement)) {
            throw new EditRefusedException("a node cannot replace itself: " + replaced);
        }
        removeConnectionsTouching(replaced);
        ModuleInfo module = modules.get(replaced.module());
        module.removeNode(replacement.node());
        module.replaceNodeInPlace(replaced.node(), replacing.withName(replaced.node()));
        redirectConnections(replacement, replaced);
        changed(NetworkChange.Kind.NODE_REPLACED, replaced.module(), replaced.node());
        return replaced;
    }

    /**
     * Merge Nodes (thesis Figure 29): one node results, at {@code first}'s place and with its name,
     * host, path and class; the parameters follow {@code policy}. Every connection of either node is
     * redirected to it; connections that become identical are kept once.
     *
     * @param first  the node that stays
     * @param second the node merged into it, which goes
     * @param policy whose parameters the result keeps
     * @return the resulting node, {@code first}
     * @throws EditRefusedException when either node is unknown, they are one node, or one is a Data and the other a
     *                              Relation
     */
    public NodeRef mergeNodes(NodeRef first, NodeRef second, MergePolicy policy) {
        NodeInfo a = requireNode(first);
        NodeInfo b = requireNode(second);
        Objects.requireNonNull(policy, "policy");
        if (first.equals(second)) {
            throw new EditRefusedException("a node cannot be merged with itself: " + first);
        }
        if (a.kind() != b.kind()) {
            throw new EditRefusedException("cannot merge " + first + " (a " + a.kind().label() + ") with " + second
                    + " (a " + b.kind().label() + "): their connections would no longer join one Data and one Relation");
        }
        modules.get(first.module()).replaceNodeInPlace(first.node(), a.withParameters(mergedParameters(a, b, policy)));
        modules.get(second.module()).removeNode(second.node());
        redirectConnections(second, first);
        for (ModuleInfo m : modules.values()) {
            List<ConnectionInfo> kept = new ArrayList<>();
            for (ConnectionInfo c : m.connections()) {
                if (kept.stream().noneMatch(k -> k.sameLink(c))) {
                    kept.add(c);
                }
            }
            m.mutableConnections().clear();
            m.mutableConnections().addAll(kept);
        }
        changed(NetworkChange.Kind.NODES_MERGED, first.module(), first.node());
        return first;
    }

    private static List<Parameter> mergedParameters(NodeInfo a, NodeInfo b, MergePolicy policy) {
        switch (policy) {
            case FIRST:
                return a.parameters();
            case SECOND:
                return b.parameters();
            case BOTH:
                List<Parameter> both = new ArrayList<>(a.parameters());
                for (Parameter p : b.parameters()) {
                    boolean clash = p.name() != null
                            ? both.stream().anyMatch(q -> p.name().equals(q.name()))
                            : both.contains(p);
                    if (!clash) {
                        both.add(p);
                    }
                }
                return both;
            default:
                throw new AssertionError(policy);
        }
    }

    // ---------------------------------------------------------------- connections

    /**
     * Adds a connection declared by {@code moduleName}; its ends must be one existing Data and one existing Relation.
     *
     * @param moduleName the module that declares it
     * @param connection the Reader or Writer
     * @throws EditRefusedException for an unknown module, a missing or wrong-kind end, or a connection some module
     *                              already declares
     */
    public void addConnection(String moduleName, ConnectionInfo connection) {
        ModuleInfo module = requireModule(moduleName);
        ModelRules.checkConnectionEnds(this, connection);
        for (LinkedConnection existing : index().connectionsOf(connection.data())) {
            if (existing.connection().sameLink(connection)) {
                throw new EditRefusedException("duplicate " + connection + " (already declared in module '" + existing.module() + "')");
            }
        }
        module.addConnection(connection);
        if (index != null) {
            index.add(moduleName, connection);
        }
        changed(NetworkChange.Kind.CONNECTION_ADDED, moduleName, connection.toString());
    }

    /**
     * Adds a connection at {@code position} among those {@code moduleName} declares: what undoing a deletion needs.
     *
     * @param moduleName the module that declares it
     * @param connection the Reader or Writer
     * @param position   its place, 0 to the module's number of connections
     * @throws EditRefusedException as {@link #addConnection(String, ConnectionInfo)}, or for {@code position} out of
     *                              range
     */
    public void addConnection(String moduleName, ConnectionInfo connection, int position) {
        ModuleInfo module = requireModule(moduleName);
        ModelRules.checkConnectionEnds(this, connection);
        for (LinkedConnection existing : index().connectionsOf(connection.data())) {
            if (existing.connection().sameLink(connection)) {
                throw new EditRefusedException("duplicate " + connection + " (already declared in module '" + existing.module() + "')");
            }
        }
        checkPosition(position, module.connections().size());
        module.mutableConnections().add(position, connection);
        index = null;
        changed(NetworkChange.Kind.CONNECTION_ADDED, moduleName, connection.toString());
    }

    /**
     * Deletes a connection.
     *
     * @param moduleName the module that declares it
     * @param connection the Reader or Writer, equal to the declared one
     * @throws EditRefusedException for an unknown module, or one that does not declare the connection
     */
    public void deleteConnection(String moduleName, ConnectionInfo connection) {
        ModuleInfo module = requireModule(moduleName);
        if (!module.mutableConnections().remove(connection)) {
            throw new EditRefusedException("module '" + moduleName + "' declares no " + connection);
        }
        changed(NetworkChange.Kind.CONNECTION_DELETED, moduleName, connection.toString());
    }

    // ---------------------------------------------------------------- internals

    private static void checkPosition(int position, int size) {
        if (position < 0 || position > size) {
            throw new EditRefusedException("position " + position + " is outside 0.." + size);
        }
    }

    private void removeConnectionsTouching(NodeRef ref) {
        for (ModuleInfo m : modules.values()) {
            m.mutableConnections().removeIf(c -> c.touches(ref));
        }
    }

    private void redirectConnections(NodeRef from, NodeRef to) {
        for (ModuleInfo m : modules.values()) {
            m.mutableConnections().replaceAll(c -> c.redirect(from, to));
        }
    }

    private ModuleInfo requireModule(String moduleName) {
        ModuleInfo module = modules.get(moduleName);
        if (module == null) {
            throw new EditRefusedException("the network has no module named '" + moduleName + "'");
        }
        return module;
    }

    private NodeInfo requireNode(NodeRef ref) {
        NodeInfo node = requireModule(ref.module()).node(ref.node());
        if (node == null) {
            throw new EditRefusedException("module '" + ref.module() + "' has no node named '" + ref.node() + "'");
        }
        return node;
    }

    private ConnectionIndex index() {
        if (index == null) {
            index = new ConnectionIndex(modules.values());
        }
        return index;
    }

    private void changed(NetworkChange.Kind kind, String module, String subject) {
        if (kind.movesConnections()) {
            index = null;
        }
        NetworkChange change = new NetworkChange(kind, module, subject);
        for (NetworkChangeListener listener : listeners) {
            try {
                listener.networkChanged(change);
            } catch (RuntimeException e) {
                LOG.warn("network change listener {} failed on {}", listener, change, e);
            }
        }
    }

    // ---------------------------------------------------------------- identity

    /** Two networks are equal when they have the same name and the same modules, nodes and connections in the same order. */
    @Override
    public boolean equals(Object o) {
        if (!(o instanceof NetworkInfo other)) {
            return false;
        }
        return Objects.equals(name, other.name)
                && new ArrayList<>(modules.values()).equals(new ArrayList<>(other.modules.values()));
    }

    @Override
    public int hashCode() {
        return Objects.hash(name, modules.keySet());
    }

    @Override
    public String toString() {
        StringBuilder sb = new StringBuilder("network ").append(name == null ? "(unnamed)" : name);
        for (Map.Entry<String, ModuleInfo> e : modules.entrySet()) {
            sb.append("\n  ").append(e.getValue());
        }
        return sb.toString();
    }
}
