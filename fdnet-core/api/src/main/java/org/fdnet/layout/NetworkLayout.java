package org.fdnet.layout;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Objects;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * The view state of one network (the .fdg side file): per module colour and visibility, per node
 * position, size and colour, keyed by module and node name. It never enters the network model, so
 * moving a node on screen never changes the .fdn file.
 */
public final class NetworkLayout {
    private String network;
    private final LinkedHashMap<String, ModuleLayout> modules = new LinkedHashMap<>();

    /**
     * The network's name as the .fdg records it (informative), or {@code null}.
     *
     * @return the name, or null
     */
    public String network() {
        return network;
    }

    /**
     * Sets the network's name the .fdg records.
     *
     * @param name the name, or null
     */
    public void setNetwork(String name) {
        network = name;
    }

    /**
     * Every module's layout.
     *
     * @return an unmodifiable live view, in the order they were added
     */
    public Collection<ModuleLayout> modules() {
        return Collections.unmodifiableCollection(modules.values());
    }

    /**
     * One module's layout.
     *
     * @param name the module's full name
     * @return its layout, or null when the file had none
     */
    public ModuleLayout module(String name) {
        return modules.get(name);
    }

    /**
     * The module's layout, created (visible, no colour) if the file had none.
     *
     * @param name the module's full name
     * @return its layout, never null
     */
    public ModuleLayout moduleOrNew(String name) {
        return modules.computeIfAbsent(name, ModuleLayout::new);
    }

    /**
     * One node's layout.
     *
     * @param ref the node's module and name
     * @return its layout, or null when it has none
     */
    public NodeLayout node(NodeRef ref) {
        ModuleLayout m = modules.get(ref.module());
        return m == null ? null : m.node(ref.node());
    }

    /**
     * Sets one node's layout, creating its module's layout when needed.
     *
     * @param ref    the node's module and name
     * @param layout its layout, not null
     */
    public void put(NodeRef ref, NodeLayout layout) {
        moduleOrNew(ref.module()).put(ref.node(), layout);
    }

    /**
     * Entries that name a module or node the network does not have (left over from edits).
     *
     * @param definition the network the layout belongs to
     * @return one text per stale entry, e.g. {@code node 'Arm/Elbow'}; empty when none
     */
    public List<String> staleEntries(NetworkInfo definition) {
        List<String> stale = new ArrayList<>();
        for (ModuleLayout m : modules.values()) {
            ModuleInfo module = definition.module(m.name());
            if (module == null) {
                stale.add("module '" + m.name() + "'");
                continue;
            }
            for (String node : m.nodes().keySet()) {
                if (!module.hasNode(node)) {
                    stale.add("node '" + m.name() + "/" + node + "'");
                }
            }
        }
        return stale;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof NetworkLayout l && Objects.equals(network, l.network)
                && new ArrayList<>(modules.values()).equals(new ArrayList<>(l.modules.values()));
    }

    @Override
    public int hashCode() {
        return Objects.hash(network, modules.keySet());
    }
}
