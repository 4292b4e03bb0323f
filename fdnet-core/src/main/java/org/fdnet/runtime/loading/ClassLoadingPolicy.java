package org.fdnet.runtime.loading;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Where node classes may come from. A node with an empty {@code path} names a built-in class: its fully
 * qualified name must lie in one of {@link #builtInPackages()} (a bare name like {@code DoubleData} means
 * {@code org.fdnet.runtime.library.DoubleData}). A node with a {@code path} names a jar, or a folder of classes
 * and/or jars, that must lie under one of {@link #allowedRoots()} — by default the network file's folder — and its
 * class is loaded by a class loader of its own per path. Nothing else is ever loaded.
 *
 * @param allowedRoots    folders under which a node's {@code path} may point (real paths are compared,
 *                        so {@code ..} and symbolic links cannot leave them)
 * @param builtInPackages package prefixes (ending in '.') of classes loadable without a path
 * @param baseDirectory   what a relative {@code path} is relative to (the network file's folder)
 */
public record ClassLoadingPolicy(List<Path> allowedRoots, List<String> builtInPackages, Path baseDirectory) {
    /** The runtime's own library. */
    public static final String LIBRARY_PACKAGE = "org.fdnet.runtime.library.";
    /** The simulated robot's nodes (module roq-sim), built in when it is on the class path. */
    public static final String ROQ_PACKAGE = "org.fdnet.roq.";

    public ClassLoadingPolicy {
        allowedRoots = List.copyOf(allowedRoots);
        builtInPackages = List.copyOf(builtInPackages);
        for (String p : builtInPackages) {
            if (!p.endsWith(".")) {
                throw new IllegalArgumentException("a built-in package prefix must end with '.': " + p);
            }
        }
    }

    /** For a network read from {@code networkFile}: its folder is the base and the one allowed root. */
    public static ClassLoadingPolicy forNetworkFile(Path networkFile, List<Path> extraRoots) {
        Path dir = networkFile.toAbsolutePath().getParent();
        List<Path> roots = new ArrayList<>();
        roots.add(dir);
        roots.addAll(extraRoots);
        return new ClassLoadingPolicy(roots, List.of(LIBRARY_PACKAGE, ROQ_PACKAGE), dir);
    }

    /** Built-in classes only: for networks built in code. */
    public static ClassLoadingPolicy builtInOnly() {
        return new ClassLoadingPolicy(List.of(), List.of(LIBRARY_PACKAGE, ROQ_PACKAGE),
                Path.of("").toAbsolutePath());
    }

    public ClassLoadingPolicy withRoots(List<Path> roots) {
        List<Path> all = new ArrayList<>(allowedRoots);
        all.addAll(roots);
        return new ClassLoadingPolicy(all, builtInPackages, baseDirectory);
    }

    public ClassLoadingPolicy withBuiltInPackage(String prefix) {
        List<String> all = new ArrayList<>(builtInPackages);
        all.add(prefix);
        return new ClassLoadingPolicy(allowedRoots, all, baseDirectory);
    }
}
