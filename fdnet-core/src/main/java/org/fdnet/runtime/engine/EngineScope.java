package org.fdnet.runtime.engine;

import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.LinkedConnection;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.NetworkEdit;
import org.fdnet.runtime.NodeDescription;
import org.fdnet.runtime.RelationState;
import org.fdnet.runtime.ServantScope;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.WholeNetwork;

/** The Servants' view of one engine: its definition, its running nodes, its controller. */
final class EngineScope implements ServantScope {
    private final RuntimeNetwork network;
    private final Controller controller;

    EngineScope(RuntimeNetwork network, Controller controller) {
        this.network = network;
        this.controller = controller;
    }

    @Override
    public WholeNetwork.Snapshot snapshot() {
        // running nodes are asked of the controller (describe), so no placement is needed here
        return new WholeNetwork.Snapshot(network.readDefinition(d -> d.copy()), controller.loadedModules(), Map.of());
    }

    @Override
    public <T> T read(Function<NetworkInfo, T> query) {
        return network.readDefinition(query);
    }

    @Override
    public NodeDescription describe(NodeRef ref) {
        record Defined(NodeInfo info, List<LinkedConnection> connections) {
        }
        Defined defined = network.readDefinition(d -> d.node(ref) == null ? null
                : new Defined(d.node(ref), List.copyOf(d.connectionsOf(ref))));
        return defined == null ? null : describe(ref, defined.info(), defined.connections());
    }

    @Override
    public NodeDescription describe(WholeNetwork.Snapshot snapshot, NodeRef ref) {
        NodeInfo info = snapshot.definition().node(ref);
        return info == null ? null : describe(ref, info, List.copyOf(snapshot.definition().connectionsOf(ref)));
    }

    private NodeDescription describe(NodeRef ref, NodeInfo info, List<LinkedConnection> connections) {
        Value value = info.kind() == NodeKind.DATA ? controller.value(ref) : null;
        RelationState state = info.kind() == NodeKind.RELATION ? controller.relationState(ref) : null;
        return new NodeDescription(ref, info, controller.nodeId(ref), value != null || state != null, value, state,
                connections);
    }

    @Override
    public boolean live(WholeNetwork.Snapshot snapshot, LinkedConnection lc) {
        ConnectionInfo c = lc.connection();
        return c.exists() && controller.value(c.data()) != null && controller.relationState(c.relation()) != null
                && controller.loadedModules().contains(lc.module());
    }

    /** This engine's own Data value or Relation state, whichever it runs (stand-ins of remote Datas included). */
    Value localValue(NodeRef ref) {
        return controller.value(ref);
    }

    RelationState localState(NodeRef ref) {
        return controller.relationState(ref);
    }

    int nodeId(NodeRef ref) {
        return controller.nodeId(ref);
    }

    @Override
    public ChangeOutcome apply(String description, NetworkEdit edit) {
        return controller.apply(description, edit);
    }

    @Override
    public ChangeOutcome load(String module) {
        return controller.load(module);
    }

    @Override
    public ChangeOutcome unload(String module) {
        return controller.unload(module);
    }

    @Override
    public ChangeOutcome hold(String module) {
        return controller.hold(module);
    }

    @Override
    public ChangeOutcome resume(String module) {
        return controller.resume(module);
    }
}
