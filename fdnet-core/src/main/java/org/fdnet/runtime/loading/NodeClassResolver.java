package org.fdnet.runtime.loading;

import java.io.IOException;
import java.lang.reflect.Modifier;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Finds and constructs node classes under a {@link ClassLoadingPolicy}.
 *
 * <pre>
 *   NodeInfo(class, path) ─┬─ path empty ─▶ built-in package? ─▶ runtime's class loader
 *                          └─ path ───────▶ real path under an allowed root? ─▶ one URLClassLoader per path
 *                                           (a jar; or a folder: its classes and every jar directly in it)
 *                                                 │
 *                          class found, is a Data/Relation as the node's kind says, public no-arg constructor
 * </pre>
 *
 * Per-path loaders delegate to the runtime's loader first, so node classes share the FDNet API classes
 * (and cannot replace them); two paths never see each other's classes.
 */
public final class NodeClassResolver implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(NodeClassResolver.class);

    private final ClassLoadingPolicy policy;
    private final Class<?> dataBase;
    private final Class<?> relationBase;
    private final ClassLoader builtIn;
    private final Map<Path, URLClassLoader> loaders = new ConcurrentHashMap<>();

    /**
     * @param dataBase     the class every Data class extends
     * @param relationBase the class every Relation class extends
     */
    public NodeClassResolver(ClassLoadingPolicy policy, Class<?> dataBase, Class<?> relationBase) {
        this.policy = policy;
        this.dataBase = dataBase;
        this.relationBase = relationBase;
        this.builtIn = NodeClassResolver.class.getClassLoader();
    }

    public ClassLoadingPolicy policy() {
        return policy;
    }

    /** A new instance of the node's class, checked against the node's kind. */
    public Object instantiate(NodeRef ref, NodeInfo node) throws NodeClassException {
        Class<?> type = resolve(ref, node);
        try {
            return type.getConstructor().newInstance();
        } catch (NoSuchMethodException e) {
            throw new NodeClassException(where(ref, node) + ": the class has no public no-argument constructor", e);
        } catch (java.lang.reflect.InvocationTargetException e) {
            throw new NodeClassException(where(ref, node) + ": the constructor threw " + e.getCause(), e.getCause());
        } catch (ReflectiveOperationException | LinkageError e) {
            throw new NodeClassException(where(ref, node) + ": cannot construct it: " + e, e);
        }
    }

    /** The node's class, checked against its kind and the policy. */
    public Class<?> resolve(NodeRef ref, NodeInfo node) throws NodeClassException {
        String name = node.className().strip();
        Class<?> type = node.path().isBlank() ? builtInClass(ref, node, name) : pathClass(ref, node, name);
        Class<?> expected = node.kind() == NodeKind.DATA ? dataBase : relationBase;
        if (!expected.isAssignableFrom(type)) {
            Class<?> other = node.kind() == NodeKind.DATA ? relationBase : dataBase;
            String is = other.isAssignableFrom(type) ? "a " + (node.kind() == NodeKind.DATA ? "Relation" : "Data") + " class"
                    : "neither a Data nor a Relation class";
            throw new NodeClassException(where(ref, node) + ": the node is a " + node.kind().label() + " but its class is "
                    + is + " (a " + node.kind().label() + " class extends " + expected.getName() + ")");
        }
        if (Modifier.isAbstract(type.getModifiers())) {
            throw new NodeClassException(where(ref, node) + ": the class is abstract");
        }
        return type;
    }

    private Class<?> builtInClass(NodeRef ref, NodeInfo node, String name) throws NodeClassException {
        String qualified = name.indexOf('.') < 0 ? ClassLoadingPolicy.LIBRARY_PACKAGE + name : name;
        boolean allowed = policy.builtInPackages().stream().anyMatch(qualified::startsWith);
        if (!allowed) {
            throw new NodeClassException(where(ref, node) + ": a class without a path must be built in (a name under "
                    + String.join(" or ", policy.builtInPackages()) + "); give the node a path to load its own class");
        }
        try {
            return Class.forName(qualified, false, builtIn);
        } catch (ClassNotFoundException | LinkageError e) {
            throw new NodeClassException(where(ref, node) + ": no such built-in class (see docs/reference/relations.md for the library)", e);
        }
    }

    private Class<?> pathClass(NodeRef ref, NodeInfo node, String name) throws NodeClassException {
        Path real = allowedPath(node.path(), where(ref, node));
        URLClassLoader loader = loaders.computeIfAbsent(real, this::newLoader);
        try {
            return Class.forName(name, false, loader);
        } catch (ClassNotFoundException e) {
            throw new NodeClassException(where(ref, node) + ": class not found under " + real, e);
        } catch (LinkageError e) {
            throw new NodeClassException(where(ref, node) + ": class under " + real + " cannot be linked: " + e, e);
        }
    }

    /**
     * The node classes a {@code path} offers, as a node with that path would load them: every public, concrete
     * Data or Relation class with a public no-argument constructor in the folder, its jars, or the jar. The classes
     * are loaded but not initialised (no static initialiser runs); one that cannot be loaded is left out.
     *
     * @param path a node's {@code path}, relative to the network file's folder
     * @return the classes, Datas and Relations together, by name
     * @throws NodeClassException when the path does not exist, is outside the allowed places, or cannot be read
     */
    public List<Class<?>> nodeClassesOn(String path) throws NodeClassException {
        Path real = allowedPath(path, "path '" + path + "'");
        URLClassLoader loader = loaders.computeIfAbsent(real, this::newLoader);
        List<String> names;
        try {
            names = NodeClassScanner.classNames(real);
        } catch (IOException e) {
            throw new NodeClassException("path '" + path + "': cannot read " + real + ": " + e.getMessage(), e);
        }
        List<Class<?>> found = new ArrayList<>();
        for (String name : names) {
            try {
                Class<?> type = Class.forName(name, false, loader);
                if (isNodeClass(type)) {
                    found.add(type);
                }
            } catch (ClassNotFoundException | LinkageError e) {
                LOG.debug("{} on {} cannot be loaded; not offered as a node class", name, real, e);
            }
        }
        found.sort(Comparator.comparing(Class::getName));
        return found;
    }

    private boolean isNodeClass(Class<?> type) {
        int modifiers = type.getModifiers();
        if (!Modifier.isPublic(modifiers) || Modifier.isAbstract(modifiers) || type.isInterface()
                || type.getDeclaringClass() != null && !Modifier.isStatic(modifiers)) {
            return false;
        }
        if (!dataBase.isAssignableFrom(type) && !relationBase.isAssignableFrom(type)) {
            return false;
        }
        try {
            type.getConstructor();
            return true;
        } catch (NoSuchMethodException | LinkageError e) {
            return false;
        }
    }

    /**
     * The real path a node's {@code path} names, when it lies under an allowed root and is a folder or a jar.
     *
     * @param where the node or path, as messages name it
     */
    private Path allowedPath(String path, String where) throws NodeClassException {
        Path given = policy.baseDirectory().resolve(path.strip());
        Path real;
        try {
            real = given.toRealPath();
        } catch (IOException e) {
            throw new NodeClassException(where + ": path '" + path + "' does not exist (" + given + ")", e);
        }
        for (Path root : policy.allowedRoots()) {
            try {
                if (real.startsWith(root.toRealPath())) {
                    if (!Files.isDirectory(real) && !NodeClassScanner.isJar(real)) {
                        throw new NodeClassException(where + ": path '" + path + "' is neither a folder nor a jar");
                    }
                    return real;
                }
            } catch (IOException e) {
                LOG.debug("allowed root {} does not exist", root, e);
            }
        }
        throw new NodeClassException(where + ": path '" + path + "' (" + real
                + ") is outside the allowed places " + policy.allowedRoots()
                + "; move the classes under the network's folder or allow their folder explicitly");
    }

    /** One loader per path: a jar; or a folder's classes and every jar directly in it. */
    private URLClassLoader newLoader(Path real) {
        List<Path> entries = new ArrayList<>();
        entries.add(real);
        if (Files.isDirectory(real)) {
            try {
                entries.addAll(NodeClassScanner.jarsIn(real));
            } catch (IOException e) {
                LOG.warn("cannot list the jars in {}; only its classes are loaded", real, e);
            }
        }
        URL[] urls = new URL[entries.size()];
        for (int i = 0; i < urls.length; i++) {
            try {
                urls[i] = entries.get(i).toUri().toURL();
            } catch (MalformedURLException e) {
                throw new IllegalStateException("cannot make a URL of " + entries.get(i), e);
            }
        }
        LOG.info("node classes from {}", entries);
        return new URLClassLoader("fdnet-nodes:" + real.getFileName(), urls, builtIn);
    }

    private static String where(NodeRef ref, NodeInfo node) {
        return "module '" + ref.module() + "', node '" + ref.node() + "', class '" + node.className() + "'"
                + (node.path().isBlank() ? "" : " (path '" + node.path() + "')");
    }

    @Override
    public void close() {
        for (URLClassLoader l : loaders.values()) {
            try {
                l.close();
            } catch (IOException e) {
                LOG.warn("closing the class loader of {} failed", l, e);
            }
        }
        loaders.clear();
    }
}
