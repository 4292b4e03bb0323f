package org.fdnet.cli;

import java.io.PrintWriter;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Data;
import org.fdnet.runtime.DeclaredParameters;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.loading.ClassLoadingPolicy;
import org.fdnet.runtime.loading.NodeClassException;
import org.fdnet.runtime.loading.NodeClassResolver;

/**
 * {@code fdnet info --params}: every node of a network with the parameters its class declares — what the file gives,
 * the default, what is allowed, whether it may change while running, what it does — and the parameters the file
 * gives that the class does not declare. Classes are found as a run finds them ({@link NodeClassResolver}).
 */
final class ParameterListing {
    private static final String ROW = "  %-16s %-14s %s%n";
    private static final String DESCRIPTION = "  %-16s %-14s   %s%n";

    private final PrintWriter out;
    private int unresolved;

    ParameterListing(PrintWriter out) {
        this.out = out;
    }

    /**
     * Lists every node of {@code network}.
     *
     * @return how many nodes' classes could not be found or read
     */
    int list(NetworkInfo network, ClassLoadingPolicy policy) {
        try (NodeClassResolver resolver = new NodeClassResolver(policy, Data.class, Relation.class)) {
            for (ModuleInfo m : network.modules()) {
                for (NodeInfo n : m.nodes()) {
                    node(resolver, new NodeRef(m.name(), n.name()), n);
                }
            }
        }
        return unresolved;
    }

    private void node(NodeClassResolver resolver, NodeRef ref, NodeInfo info) {
        out.printf("%n%s %s (%s)%n", info.kind().label(), ref, info.className());
        DeclaredParameters declared;
        try {
            declared = DeclaredParameters.of(resolver.resolve(ref, info));
        } catch (NodeClassException | RuntimeException | LinkageError e) {
            unresolved++;
            out.println("  cannot list its parameters: " + e.getMessage());
            return;
        }
        NodeParameters given = NodeParameters.of(ref, info);
        for (ParameterSpec<?> spec : declared.all()) {
            String text = given.text(spec.name());
            out.printf(ROW, spec.name(), text == null ? "-" : text.strip(), spec.requirement() + "; " + defaultOf(spec)
                    + (spec.isLive() ? "; may change while running" : "; fixed while running"));
            if (!spec.description().isEmpty()) {
                out.printf(DESCRIPTION, "", "", spec.description());
            }
        }
        for (String name : declared.undeclared(given)) {
            out.printf(ROW, name, given.text(name).strip(), "not declared by " + declared.nodeClass().getSimpleName());
        }
    }

    private static String defaultOf(ParameterSpec<?> spec) {
        if (spec.defaultText() != null) {
            return "default " + spec.defaultText();
        }
        return spec.isRequired() ? "required" : "optional";
    }
}
