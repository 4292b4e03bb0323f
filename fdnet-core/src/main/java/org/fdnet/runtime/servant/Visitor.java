package org.fdnet.runtime.servant;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/** The Visitor servant: finds nodes of the network (running ones, or all the definition holds). */
public final class Visitor {
    private final org.fdnet.runtime.RuntimeNetwork network;
    private final Reflect reflect;

    Visitor(org.fdnet.runtime.RuntimeNetwork network, Reflect reflect) {
        this.network = network;
        this.reflect = reflect;
    }

    /** Running nodes that match, in definition order. */
    public List<NodeDescription> find(Predicate<NodeDescription> filter) {
        List<NodeDescription> result = new ArrayList<>();
        for (NodeRef ref : defined()) {
            NodeDescription d = reflect.describe(ref);
            if (d != null && d.running() && filter.test(d)) {
                result.add(d);
            }
        }
        return result;
    }

    /** Running Datas. */
    public List<NodeDescription> datas() {
        return find(d -> d.kind() == NodeKind.DATA);
    }

    /** Running Relations. */
    public List<NodeDescription> relations() {
        return find(d -> d.kind() == NodeKind.RELATION);
    }

    /** Running nodes whose class is {@code className} (fully qualified, or the simple name). */
    public List<NodeDescription> byClass(String className) {
        return find(d -> d.className().equals(className) || d.className().endsWith("." + className));
    }

    /** Running nodes called {@code name} in any module. */
    public List<NodeDescription> byName(String name) {
        return find(d -> d.ref().node().equals(name));
    }

    /** Every node the definition holds, loaded or not, in order. */
    public List<NodeRef> defined() {
        return network.readDefinition(def -> {
            List<NodeRef> refs = new ArrayList<>();
            for (ModuleInfo m : def.modules()) {
                for (NodeInfo n : m.nodes()) {
                    refs.add(new NodeRef(m.name(), n.name()));
                }
            }
            return refs;
        });
    }
}
