package org.fdnet.netinfo;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * Nested modules: a module may hold modules, named by path ({@code Arm/Hand}). What loads and unloads together:
 * loading a module loads its children marked {@code loadatstart} (and theirs, and so on); unloading it unloads every
 * module below it; at start, {@code main}, the top-level modules marked {@code loadatstart} and, below each of them,
 * the children marked so. A child whose parent is not loaded is never loaded.
 */
public final class ModuleTree {
    private ModuleTree() {
    }

    /**
     * The enclosing module of {@code path}, or {@code null} when it is a top-level module.
     *
     * @param path a module's full name, e.g. {@code Arm/Hand}
     * @return the parent's full name ({@code Arm}), or null
     */
    public static String parentOf(String path) {
        int slash = path.lastIndexOf('/');
        return slash < 0 ? null : path.substring(0, slash);
    }

    /**
     * Whether {@code path} is {@code ancestor} or a module below it.
     *
     * @param path     a module's full name
     * @param ancestor another module's full name
     * @return true when {@code path} equals {@code ancestor} or starts with {@code ancestor/}
     */
    public static boolean within(String path, String ancestor) {
        return path.equals(ancestor) || path.startsWith(ancestor + "/");
    }

    /**
     * The modules directly below {@code path}, in declaration order.
     *
     * @param network the network whose modules are looked at
     * @param path    a module's full name
     * @return a new list, empty when it has no children
     */
    public static List<ModuleInfo> children(NetworkInfo network, String path) {
        List<ModuleInfo> children = new ArrayList<>();
        for (ModuleInfo m : network.modules()) {
            if (path.equals(m.parentName())) {
                children.add(m);
            }
        }
        return children;
    }

    /**
     * {@code path} and every module below it, parents before children.
     *
     * @param network the network whose modules are looked at
     * @param path    a module's full name
     * @return a new list of full names, in declaration order; empty when the network has no such module
     */
    public static List<String> subtree(NetworkInfo network, String path) {
        List<String> subtree = new ArrayList<>();
        for (ModuleInfo m : network.modules()) {
            if (within(m.name(), path)) {
                subtree.add(m.name());
            }
        }
        return subtree;
    }

    /**
     * The modules a network loads when it starts, parents before children.
     *
     * @param network the network whose modules are looked at
     * @return a new set of full names, {@code main} included
     */
    public static Set<String> atStart(NetworkInfo network) {
        Set<String> loaded = new LinkedHashSet<>();
        for (ModuleInfo m : network.modules()) {
            String parent = m.parentName();
            if (m.loadAtStart() && (parent == null || loaded.contains(parent))) {
                loaded.add(m.name());
            }
        }
        return loaded;
    }

    /**
     * The modules that load when {@code module} is loaded on top of {@code loaded}: the module and, below it, its
     * children marked {@code loadatstart}, recursively. The module's own parent must be loaded (else the result is
     * empty: see {@link #whyNotLoadable}).
     *
     * @param network the network whose modules are looked at
     * @param module  the module to load
     * @return a new set of full names, {@code module} first
     */
    public static Set<String> loadedWith(NetworkInfo network, String module) {
        Set<String> added = new LinkedHashSet<>();
        added.add(module);
        for (ModuleInfo m : network.modules()) {
            String parent = m.parentName();
            if (parent != null && m.loadAtStart() && added.contains(parent) && within(m.name(), module)) {
                added.add(m.name());
            }
        }
        return added;
    }

    /**
     * The reason {@code module} cannot be loaded on top of {@code loaded}, or {@code null} when it can.
     *
     * @param network the network whose modules are looked at
     * @param loaded  the modules running now
     * @param module  the module to load
     * @return a message naming the module (unknown, already loaded, or its parent not loaded), or null
     */
    public static String whyNotLoadable(NetworkInfo network, Set<String> loaded, String module) {
        if (network.module(module) == null) {
            return "the network has no module named '" + module + "'";
        }
        if (loaded.contains(module)) {
            return "module '" + module + "' is already loaded";
        }
        String parent = parentOf(module);
        if (parent != null && !loaded.contains(parent)) {
            return "module '" + module + "' is inside module '" + parent + "', which is not loaded: load '" + parent + "' first";
        }
        return null;
    }

    /**
     * {@code loaded} after loading {@code module} (and its loadatstart children).
     *
     * @param network the network whose modules are looked at
     * @param loaded  the modules running now; not changed
     * @param module  the module to load
     * @return a new set
     */
    public static Set<String> afterLoad(NetworkInfo network, Set<String> loaded, String module) {
        Set<String> next = new LinkedHashSet<>(loaded);
        next.addAll(loadedWith(network, module));
        return next;
    }

    /**
     * {@code loaded} after unloading {@code module} and every module below it.
     *
     * @param loaded the modules running now; not changed
     * @param module the module to unload
     * @return a new set
     */
    public static Set<String> afterUnload(Set<String> loaded, String module) {
        Set<String> next = new LinkedHashSet<>(loaded);
        next.removeIf(m -> within(m, module));
        return next;
    }
}
