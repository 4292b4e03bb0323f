package org.fdnet.control;

import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeListener;
import org.fdnet.runtime.Controller;
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
public final class LocalLiveNetwork extends ControlledLiveNetwork {
    private final Controller controller;
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
            return datasOf(controller.snapshot(), controller.loadedModules());
        }
    };

    private final Optional<String> loggerViewerAddress;

    public LocalLiveNetwork(String name, Controller controller) {
        this(name, controller, Optional.empty());
    }

    /** {@code loggerViewerAddress}: {@code HOST:PORT} of the viewer service of the logger recording this run, if known. */
    public LocalLiveNetwork(String name, Controller controller, Optional<String> loggerViewerAddress) {
        super(name, controller);
        this.controller = controller;
        this.loggerViewerAddress = Objects.requireNonNull(loggerViewerAddress, "loggerViewerAddress");
    }

    @Override
    public Optional<String> loggerViewerAddress() {
        return loggerViewerAddress;
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
    protected SampledNetwork sampled() {
        return sampled;
    }
}
