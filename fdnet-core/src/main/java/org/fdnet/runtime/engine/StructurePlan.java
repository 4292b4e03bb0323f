package org.fdnet.runtime.engine;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Placement;

/**
 * What should be running for a definition, a set of loaded modules and a placement: the local nodes,
 * stand-ins for remote Datas that local Relations touch, the connections to make (both ends present,
 * declared by a loaded module, {@code exist} = yes), and each local Relation's declared connections
 * in order (the slots of its wiring, present or not). Pure: computing it changes nothing.
 */
final class StructurePlan {
    final Map<NodeRef, NodeInfo> local = new LinkedHashMap<>();
    final Map<NodeRef, NodeInfo> standIns = new LinkedHashMap<>();
    final Set<LiveLink> links = new LinkedHashSet<>();
    final List<RemoteDraft> remote = new ArrayList<>();
    final Map<NodeRef, List<LiveLink>> declared = new HashMap<>();

    record RemoteDraft(ConnectionInfo connection, String remoteEnd, String host) {
    }

    static StructurePlan of(NetworkInfo definition, Set<String> loaded, Placement placement) {
        StructurePlan plan = new StructurePlan();
        Map<NodeRef, NodeInfo> elsewhere = new HashMap<>();
        for (ModuleInfo m : definition.modules()) {
            if (!loaded.contains(m.name())) {
                continue;
            }
            for (NodeInfo n : m.nodes()) {
                NodeRef ref = new NodeRef(m.name(), n.name());
                if (placement.isLocal(ref, n)) {
                    plan.local.put(ref, n);
                } else {
                    elsewhere.put(ref, n);
                }
            }
        }
        for (ModuleInfo m : definition.modules()) {
            if (!loaded.contains(m.name())) {
                continue;
            }
            for (ConnectionInfo c : m.connections()) {
                if (!c.exists()) {
                    continue;
                }
                LiveLink link = LiveLink.of(c);
                boolean relationHere = plan.local.containsKey(c.relation());
                boolean dataHere = plan.local.containsKey(c.data());
                if (relationHere) {
                    plan.declared.computeIfAbsent(c.relation(), k -> new ArrayList<>()).add(link);
                }
                if (relationHere && dataHere) {
                    plan.links.add(link);
                } else if (relationHere && elsewhere.containsKey(c.data())) {
                    plan.standIns.put(c.data(), elsewhere.get(c.data()));
                    plan.links.add(link);
                    plan.remote.add(new RemoteDraft(c, "data", elsewhere.get(c.data()).host()));
                } else if (dataHere && elsewhere.containsKey(c.relation())) {
                    plan.remote.add(new RemoteDraft(c, "relation", elsewhere.get(c.relation()).host()));
                }
            }
        }
        return plan;
    }
}
