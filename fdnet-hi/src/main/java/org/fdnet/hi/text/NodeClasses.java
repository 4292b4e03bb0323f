package org.fdnet.hi.text;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.function.Supplier;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Data;
import org.fdnet.runtime.DeclaredParameters;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.loading.ClassLoadingPolicy;
import org.fdnet.runtime.loading.NodeClassException;
import org.fdnet.runtime.loading.NodeClassResolver;

/**
 * What the node form knows of node classes, found as a run finds them ({@link NodeClassResolver} under the policy of
 * the network's file): the Data and Relation classes the network's paths offer, and the parameters a node's class
 * declares. A path is scanned once; {@link #forget} scans again (the user rebuilt a jar). A network not saved yet has
 * no folder, so only built-in classes are found.
 */
final class NodeClasses implements AutoCloseable {
    /** A class a node may name, with the path that offers it. */
    record Choice(String className, String path) {
        @Override
        public String toString() {
            return className + " (" + path + ")";
        }
    }

    /** A node class's declarations, or why they cannot be read. */
    record Declared(DeclaredParameters parameters, String problem) {
    }

    private final Supplier<Path> networkFile;
    private Path resolverFile;
    private NodeClassResolver resolver;
    private final Map<String, List<Class<?>>> scanned = new HashMap<>();
    private final Map<String, String> problems = new HashMap<>();
    private String lastScanProblem;

    NodeClasses(Supplier<Path> networkFile) {
        this.networkFile = networkFile;
    }

    private NodeClassResolver resolver() {
        Path file = networkFile.get();
        if (resolver == null || !Objects.equals(file, resolverFile)) {
            close();
            if (!Objects.equals(file, resolverFile)) {
                scanned.clear(); // paths are relative to the file's folder
                problems.clear();
            }
            resolverFile = file;
            ClassLoadingPolicy policy = file == null ? ClassLoadingPolicy.builtInOnly()
                    : ClassLoadingPolicy.forNetworkFile(file, List.of());
            resolver = new NodeClassResolver(policy, Data.class, Relation.class);
        }
        return resolver;
    }

    /** The classes of {@code kind} the network's paths and {@code typedPath} offer, by path, then by name. */
    List<Choice> choices(NetworkInfo network, String typedPath, NodeKind kind) {
        Set<String> paths = new LinkedHashSet<>();
        for (ModuleInfo m : network.modules()) {
            for (NodeInfo n : m.nodes()) {
                if (!n.path().isBlank()) {
                    paths.add(n.path().strip());
                }
            }
        }
        if (typedPath != null && !typedPath.isBlank()) {
            paths.add(typedPath.strip());
        }
        Class<?> base = kind == NodeKind.DATA ? Data.class : Relation.class;
        List<Choice> found = new ArrayList<>();
        List<String> unreadable = new ArrayList<>();
        for (String path : paths) {
            for (Class<?> c : scan(path)) {
                if (base.isAssignableFrom(c)) {
                    found.add(new Choice(c.getName(), path));
                }
            }
            if (problems.containsKey(path)) {
                unreadable.add(problems.get(path));
            }
        }
        lastScanProblem = unreadable.isEmpty() ? null : String.join("; ", unreadable);
        return found;
    }

    private List<Class<?>> scan(String path) {
        NodeClassResolver r = resolver();
        List<Class<?>> found = scanned.get(path);
        if (found == null) {
            try {
                found = r.nodeClassesOn(path);
            } catch (NodeClassException e) {
                problems.put(path, e.getMessage());
                found = List.of();
            }
            scanned.put(path, found);
        }
        return found;
    }

    /** Why a path of the last {@link #choices} could not be read, or {@code null}. */
    String scanProblem() {
        return lastScanProblem;
    }

    /** The parameters the class of a node being typed declares. */
    Declared declared(NodeKind kind, String path, String className) {
        if (className == null || className.isBlank()) {
            return new Declared(null, "type the node's class to see its parameters");
        }
        NodeInfo draft = new NodeInfo(kind, "draft", "localhost", path == null ? "" : path, className, List.of());
        try {
            return new Declared(DeclaredParameters.of(resolver().resolve(new NodeRef("main", "draft"), draft)), null);
        } catch (NodeClassException e) {
            return new Declared(null, e.getMessage().replace("module 'main', node 'draft', ", ""));
        } catch (RuntimeException | LinkageError e) {
            return new Declared(null, "class '" + className + "': its parameters cannot be read: " + e);
        }
    }

    /** Scans every path again at the next {@link #choices}. */
    void forget() {
        scanned.clear();
        problems.clear();
        close();
    }

    @Override
    public void close() {
        if (resolver != null) {
            resolver.close();
            resolver = null;
        }
    }
}
