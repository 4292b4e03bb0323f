package org.fdnet.runtime.cli;

import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;

/**
 * One {@code --param MODULE/NODE:NAME=VALUE} of {@code fdnet run} and of the benchmarks that run a network file: a
 * node, one of its parameters and the text of its value (a bare node name means module main). A run applies it to the
 * running network ({@code NetworkControl.setParameter}); a benchmark that starts many runs of one definition applies
 * it to the definition first ({@link #applyTo}).
 */
public record ParameterAssignment(NodeRef node, String name, String value) {
    /** @throws IllegalArgumentException with the message to print after {@code --param TEXT: } */
    public static ParameterAssignment parse(String text) {
        int colon = text.indexOf(':');
        int eq = text.indexOf('=', Math.max(colon, 0));
        if (colon <= 0 || eq < 0 || eq == colon + 1) {
            throw new IllegalArgumentException("expected MODULE/NODE:NAME=VALUE");
        }
        return new ParameterAssignment(NodeRef.parse(text.substring(0, colon).strip(), ModuleInfo.MAIN),
                text.substring(colon + 1, eq).strip(), text.substring(eq + 1));
    }

    /**
     * Sets this parameter in {@code network}'s definition, keeping the type the file gives it.
     *
     * @throws IllegalArgumentException naming the node or the parameter when the definition has no such one
     */
    public void applyTo(NetworkInfo network) {
        if (network.node(node) == null) {
            throw new IllegalArgumentException("no node " + node + " in " + network.name());
        }
        List<Parameter> parameters = new ArrayList<>();
        boolean found = false;
        for (Parameter p : network.node(node).parameters()) {
            if (p.name().equals(name)) {
                parameters.add(new Parameter(name, p.type(), value));
                found = true;
            } else {
                parameters.add(p);
            }
        }
        if (!found) {
            throw new IllegalArgumentException("node " + node + " of " + network.name() + " has no parameter " + name
                    + " in its file");
        }
        network.setParameters(node, parameters);
    }
}
