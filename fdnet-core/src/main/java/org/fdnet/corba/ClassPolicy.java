package org.fdnet.corba;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.NodeInfo;

/**
 * Which node classes a remote create may instantiate on this host: FDNet's built-in classes (empty
 * {@code path}, class in {@code org.fdnet.}), or classes whose {@code path} lies inside one of the
 * folders the host was started with ({@code --allow-path}). Anything else is refused before a class is
 * loaded, so a network file from another machine cannot run arbitrary code here.
 */
public final class ClassPolicy {
    private static final String BUILT_IN_PACKAGE = "org.fdnet.";

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
            return node.className().startsWith(BUILT_IN_PACKAGE) ? null
                    : "class " + node.className() + " has no path and is not a built-in (" + BUILT_IN_PACKAGE
                    + "*) class";
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
