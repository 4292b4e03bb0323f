package org.fdnet.control;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkControl;
import org.fdnet.runtime.NetworkEdit;

/**
 * A {@link LiveNetwork} of a run in this process, over the run's own {@link NetworkControl}: every change goes to
 * that control as it is, and every subscriber is one {@link LiveSubscription} on the {@link SampledNetwork} the
 * subclass gives (one host: the engine's controller; across hosts: each Data read on its home host).
 */
public abstract class ControlledLiveNetwork implements LiveNetwork {
    private final String name;
    private final NetworkControl control;
    private LiveSubscriptions subscriptions;

    protected ControlledLiveNetwork(String name, NetworkControl control) {
        this.name = Objects.requireNonNull(name, "name");
        this.control = Objects.requireNonNull(control, "control");
    }

    /** What subscribers listen to and sample. */
    protected abstract SampledNetwork sampled();

    /** The Datas of the loaded modules of {@code definition}, in definition order. */
    protected static List<NodeRef> datasOf(NetworkInfo definition, Set<String> loaded) {
        List<NodeRef> datas = new ArrayList<>();
        for (ModuleInfo m : definition.modules()) {
            if (!loaded.contains(m.name())) {
                continue;
            }
            for (NodeInfo n : m.nodes()) {
                if (n.kind() == NodeKind.DATA) {
                    datas.add(new NodeRef(m.name(), n.name()));
                }
            }
        }
        return datas;
    }

    @Override
    public final String name() {
        return name;
    }

    @Override
    public ChangeOutcome apply(String description, NetworkEdit edit) {
        return control.apply(description, edit);
    }

    @Override
    public ChangeOutcome load(String module) {
        return control.load(module);
    }

    @Override
    public ChangeOutcome unload(String module) {
        return control.unload(module);
    }

    @Override
    public ChangeOutcome hold(String module) {
        return control.hold(module);
    }

    @Override
    public ChangeOutcome resume(String module) {
        return control.resume(module);
    }

    @Override
    public ChangeOutcome setParameter(NodeRef node, String parameter, String value) {
        return control.setParameter(node, parameter, value);
    }

    @Override
    public ChangeOutcome send(NodeRef data, String text) {
        return control.send(data, text);
    }

    @Override
    public AutoCloseable subscribe(LiveNetworkListener listener) {
        return subscriptions().open(listener);
    }

    /**
     * Tells every subscriber that the network stopped ({@code disconnected(reason)}, their last call) and ends
     * their subscriptions. The run calls it when it stops the network.
     */
    public void networkStopped(String reason) {
        subscriptions().networkStopped(reason);
    }

    /** Ends every subscription; the network keeps running. */
    @Override
    public void close() {
        subscriptions().closeAll();
    }

    private synchronized LiveSubscriptions subscriptions() {
        if (subscriptions == null) {
            subscriptions = new LiveSubscriptions(name, sampled());
        }
        return subscriptions;
    }
}
