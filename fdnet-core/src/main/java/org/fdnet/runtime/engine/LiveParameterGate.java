package org.fdnet.runtime.engine;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.DeclaredParameters;
import org.fdnet.runtime.ParameterSpec;

/**
 * Guards live parameter changes: a change to a running node (the controller's set-parameter, an editor's edit, a
 * Servant's) may only touch parameters its class declares {@link ParameterSpec#live() live}. Parameters a class does
 * not declare are not judged. A node whose class or path changes is a new node, not a parameter change.
 */
final class LiveParameterGate {
    private LiveParameterGate() {
    }

    /**
     * Why the running node cannot take {@code next}'s parameters, or {@code null} when it can.
     *
     * @param running      the node's definition as it runs
     * @param runningClass the class of its running instance
     */
    static String refusal(NodeRef ref, NodeInfo running, Class<?> runningClass, NodeInfo next) {
        if (!running.className().equals(next.className()) || !running.path().equals(next.path())) {
            return null;
        }
        DeclaredParameters declared = DeclaredParameters.of(runningClass);
        List<String> fixed = new ArrayList<>();
        for (String name : changedNames(running.parameters(), next.parameters())) {
            ParameterSpec<?> spec = declared.find(name);
            if (spec != null && !spec.isLive()) {
                fixed.add("'" + name + "'");
            }
        }
        if (fixed.isEmpty()) {
            return null;
        }
        return ref.spelledOut() + ": parameter" + (fixed.size() == 1 ? " " : "s ") + String.join(", ", fixed)
                + " of " + runningClass.getSimpleName() + (fixed.size() == 1 ? " is" : " are")
                + " read once at start and cannot change while the network runs; change the file and start it again";
    }

    private static List<String> changedNames(List<Parameter> before, List<Parameter> after) {
        List<String> names = new ArrayList<>();
        for (Parameter p : before) {
            if (p.name() != null && !Objects.equals(value(after, p.name()), p.value())) {
                names.add(p.name());
            }
        }
        for (Parameter p : after) {
            if (p.name() != null && value(before, p.name()) == null && !names.contains(p.name())) {
                names.add(p.name());
            }
        }
        return names;
    }

    private static String value(List<Parameter> parameters, String name) {
        for (Parameter p : parameters) {
            if (name.equals(p.name())) {
                return p.value();
            }
        }
        return null;
    }
}
