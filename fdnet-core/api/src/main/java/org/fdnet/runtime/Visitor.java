package org.fdnet.runtime;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/** The Visitor servant: finds nodes of the network (running ones, or all the definition holds). */
public final class Visitor {
    private final ServantScope scope;

    Visitor(ServantScope scope) {
        this.scope = scope;
    }

    /**
     * Running nodes that match, in definition order (on every host, when the network spans several).
     *
     * @param filter the test a node's description must pass
     * @return a new list, from one snapshot of the network
     */
    public List<NodeDescription> find(Predicate<NodeDescription> filter) {
        List<NodeDescription> result = new ArrayList<>();
        WholeNetwork.Snapshot snapshot = scope.snapshot();
        for (NodeRef ref : refs(snapshot.definition())) {
            NodeDescription d = scope.describe(snapshot, ref);
            if (d != null && d.running() && filter.test(d)) {
                result.add(d);
            }
        }
        return result;
    }

    /**
     * Running Datas.
     *
     * @return their descriptions, in definition order
     */
    public List<NodeDescription> datas() {
        return find(d -> d.kind() == NodeKind.DATA);
    }

    /**
     * Running Relations.
     *
     * @return their descriptions, in definition order
     */
    public List<NodeDescription> relations() {
        return find(d -> d.kind() == NodeKind.RELATION);
    }

    /**
     * Running nodes whose class is {@code className} (fully qualified, or the simple name); a node that names a
     * library class by its bare name ({@code DoubleSensor}) matches the qualified name too.
     *
     * @param className e.g. {@code org.fdnet.runtime.library.LowPass} or {@code LowPass}
     * @return their descriptions, in definition order
     */
    public List<NodeDescription> byClass(String className) {
        String simple = className.substring(className.lastIndexOf('.') + 1);
        return find(d -> d.className().equals(className) || d.className().endsWith("." + className)
                || d.className().equals(simple));
    }

    /**
     * Running nodes called {@code name} in any module.
     *
     * @param name the node name, without its module
     * @return their descriptions, in definition order
     */
    public List<NodeDescription> byName(String name) {
        return find(d -> d.ref().node().equals(name));
    }

    /**
     * Every node the definition holds, loaded or not, in order.
     *
     * @return a new list, module by module
     */
    public List<NodeRef> defined() {
        return scope.read(Visitor::refs);
    }

    private static List<NodeRef> refs(NetworkInfo definition) {
        List<NodeRef> refs = new ArrayList<>();
        for (ModuleInfo m : definition.modules()) {
            for (NodeInfo n : m.nodes()) {
                refs.add(new NodeRef(m.name(), n.name()));
            }
        }
        return refs;
    }
}
