package org.fdnet.control;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeListener;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.NetworkEdit;
import org.fdnet.runtime.Value;

/**
 * A {@link LiveNetwork} over the {@link Controller} of a network running in this process.
 *
 * <pre>
 *   apply(base, edited) ──NetworkDiff.between(base, edited).asEdit()──▶ controller.apply (all or nothing)
 *   controller ──change settled──▶ Subscription queue ──┐
 *   every 100 ms: controller.value(Data) per Data ──────┴─▶ one thread per subscriber ─▶ LiveNetworkListener
 * </pre>
 *
 * Values are sampled, not observed: the sampler reads each running Data's latest value ten times a second
 * and reports those whose value object changed since its previous look (every write publishes a new one), so a
 * subscriber costs the writing Relations nothing.
 */
public final class LocalLiveNetwork implements LiveNetwork {
    private final String name;
    private final Controller controller;
    private final LiveSubscriptions subscriptions;
    private final SampledNetwork sampled = new SampledNetwork() {
        @Override
        public void addChangeListener(ChangeListener listener) {
            controller.addChangeListener(listener);
        }

        @Override
        public void removeChangeListener(ChangeListener listener) {
            controller.removeChangeListener(listener);
        }

        @Override
        public Value value(NodeRef data) {
            return controller.value(data);
        }

        @Override
        public List<NodeRef> runningDatas() {
            return LocalLiveNetwork.this.runningDatas();
        }
    };

    private final Optional<String> loggerViewerAddress;

    public LocalLiveNetwork(String name, Controller controller) {
        this(name, controller, Optional.empty());
    }

    /** {@code loggerViewerAddress}: {@code HOST:PORT} of the viewer service of the logger recording this run, if known. */
    public LocalLiveNetwork(String name, Controller controller, Optional<String> loggerViewerAddress) {
        this.name = Objects.requireNonNull(name, "name");
        this.controller = Objects.requireNonNull(controller, "controller");
        this.loggerViewerAddress = Objects.requireNonNull(loggerViewerAddress, "loggerViewerAddress");
        this.subscriptions = new LiveSubscriptions(name, sampled);
    }

    @Override
    public Optional<String> loggerViewerAddress() {
        return loggerViewerAddress;
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public NetworkInfo snapshot() {
        return controller.snapshot();
    }

    @Override
    public Set<String> loadedModules() {
        return controller.loadedModules();
    }

    @Override
    public Set<String> heldModules() {
        return controller.heldModules();
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

    @Override
    public ChangeOutcome setParameter(NodeRef node, String parameter, String value) {
        return controller.setParameter(node, parameter, value);
    }

    @Override
    public ChangeOutcome send(NodeRef data, String text) {
        return controller.send(data, text);
    }

    @Override
    public AutoCloseable subscribe(LiveNetworkListener listener) {
        return subscriptions.open(listener);
    }

    /**
     * Tells every subscriber that the network stopped ({@code disconnected(reason)}, their last call) and ends
     * their subscriptions. The run calls it when it stops the network.
     */
    public void networkStopped(String reason) {
        subscriptions.networkStopped(reason);
    }

    /** Ends every subscription; the network keeps running. */
    @Override
    public void close() {
        subscriptions.closeAll();
    }

    private List<NodeRef> runningDatas() {
        NetworkInfo now = controller.snapshot();
        Set<String> loaded = controller.loadedModules();
        List<NodeRef> datas = new ArrayList<>();
        for (ModuleInfo m : now.modules()) {
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
}
