package org.fdnet.runtime.engine;

import java.util.List;
import java.util.function.Function;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.LinkedConnection;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkEdit;
import org.fdnet.runtime.NodeDescription;
import org.fdnet.runtime.RelationState;
import org.fdnet.runtime.ServantScope;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.WholeNetwork;

/**
 * The Servants' view of a network over several hosts: definition, placement and changes come from the
 * {@link WholeNetwork}; what runs on this host (its own nodes and its stand-ins of remote Datas) is read from its
 * engine, any other Data's value from the host it runs on. A Relation on another host has no state here
 * ({@code null}); whether it runs is known.
 */
final class WholeNetworkScope implements ServantScope {
    private final EngineScope engine;
    private final WholeNetwork whole;

    WholeNetworkScope(EngineScope engine, WholeNetwork whole) {
        this.engine = engine;
        this.whole = whole;
    }

    @Override
    public WholeNetwork.Snapshot snapshot() {
        return whole.snapshot();
    }

    @Override
    public <T> T read(Function<NetworkInfo, T> query) {
        return query.apply(whole.snapshot().definition());
    }

    @Override
    public NodeDescription describe(NodeRef ref) {
        return describe(whole.snapshot(), ref);
    }

    @Override
    public NodeDescription describe(WholeNetwork.Snapshot snapshot, NodeRef ref) {
        NodeInfo info = snapshot.definition().node(ref);
        if (info == null) {
            return null;
        }
        boolean running = snapshot.running(ref);
        Value value = null;
        RelationState state = null;
        if (info.kind() == NodeKind.DATA) {
            value = engine.localValue(ref);
            if (value == null && running) {
                value = whole.value(ref);
            }
        } else {
            state = engine.localState(ref);
        }
        return new NodeDescription(ref, info, engine.nodeId(ref), running, value, state,
                List.copyOf(snapshot.definition().connectionsOf(ref)));
    }

    @Override
    public boolean live(WholeNetwork.Snapshot snapshot, LinkedConnection lc) {
        ConnectionInfo c = lc.connection();
        return c.exists() && snapshot.running(c.data()) && snapshot.running(c.relation())
                && snapshot.loaded().contains(lc.module());
    }

    @Override
    public ChangeOutcome apply(String description, NetworkEdit edit) {
        return whole.apply(description, edit);
    }

    @Override
    public ChangeOutcome load(String module) {
        return whole.load(module);
    }

    @Override
    public ChangeOutcome unload(String module) {
        return whole.unload(module);
    }

    @Override
    public ChangeOutcome hold(String module) {
        return whole.hold(module);
    }

    @Override
    public ChangeOutcome resume(String module) {
        return whole.resume(module);
    }
}
