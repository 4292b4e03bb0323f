package org.fdnet.corba;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.runtime.loading.ClassLoadingPolicy;

/**
 * Which node classes a remote create may instantiate on this host: FDNet's built-in classes (empty
 * {@code path}, a bare library name or a class in {@link #BUILT_IN_PACKAGES}), or classes whose
 * {@code path} lies inside one of the
 * folders the host was started with ({@code --allow-path}). Anything else is refused before a class is
 * loaded, so a network file from another machine cannot run arbitrary code here.
 */
public final class ClassPolicy {
    /** Packages whose classes need no path: the runtime's library, the simulated robot, the benchmark's. */
    public static final List<String> BUILT_IN_PACKAGES = List.of(ClassLoadingPolicy.LIBRARY_PACKAGE,
            ClassLoadingPolicy.ROQ_PACKAGE, "org.fdnet.corba.bench.");

    private final List<Path> allowed;

    public ClassPolicy(List<Path> allowedPaths) {
        List<Path> real = new ArrayList<>();
        for (Path p : allowedPaths) {
            try {
                real.add(p.toRealPath());
            } catch (IOException e) {
                throw new IllegalArgumentException("allowed path " + p + " does not exist", e);
            }
        }
        this.allowed = List.copyOf(real);
    }

    public List<Path> allowedPaths() {
        return allowed;
    }

    /** Why {@code node} may not be created here, or {@code null} when it may. */
    public String refusal(NodeInfo node) {
        if (node.path().isEmpty()) {
            String c = node.className();
            boolean builtIn = !c.contains(".") || BUILT_IN_PACKAGES.stream().anyMatch(c::startsWith);
            return builtIn ? null
                    : "class " + c + " of " + node.name() + " has no path and is not built in (" + BUILT_IN_PACKAGES + ")";
        }
        Path real;
        try {
            Path p = Path.of(node.path());
            if (!p.isAbsolute()) {
                return "path '" + node.path() + "' of " + node.name() + " must be absolute for a remote create";
            }
            real = Files.exists(p) ? p.toRealPath() : p.normalize();
        } catch (IOException | InvalidPathException e) {
            return "path '" + node.path() + "' of " + node.name() + " is not usable: " + e.getMessage();
        }
        for (Path root : allowed) {
            if (real.startsWith(root)) {
                return null;
            }
        }
        return "path " + real + " of " + node.name() + " is outside this host's allowed paths " + allowed
                + " (start the host with --allow-path)";
    }
}
