package org.fdnet.corba.control;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.fdnet.control.ControlledLiveNetwork;
import org.fdnet.control.SampledNetwork;
import org.fdnet.corba.DistributedControl;
import org.fdnet.corba.IdlMapping;
import org.fdnet.corba.NetworkDeployment;
import org.fdnet.corba.ValueCodec;
import org.fdnet.corba.idl.Host;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeListener;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Value;
import org.omg.CORBA.SystemException;

/**
 * A {@link LiveNetwork} of a run across hosts, over its two-phase {@link DistributedControl}: every change settled
 * there — the control object's, {@code fdnet run}'s standard-input commands, a Relation's Servants on any host — is
 * told to subscribers. The snapshot is the running definition, including what Relations built through Paste. Values
 * are sampled by reading each running Data from its home host ({@code Host.read}) ten times a second; a Data is
 * reported when its value differs from the previous sample.
 */
public final class DistributedLiveNetwork extends ControlledLiveNetwork implements SampledNetwork {
    private final DistributedControl control;
    private final NetworkDeployment deployment;
    private final Set<String> held = ConcurrentHashMap.newKeySet();
    private final Map<NodeRef, Value> lastRead = new ConcurrentHashMap<>();

    private final Optional<String> loggerViewerAddress;

    public DistributedLiveNetwork(String name, DistributedControl control, NetworkDeployment deployment) {
        this(name, control, deployment, Optional.empty());
    }

    /** {@code loggerViewerAddress}: {@code HOST:PORT} of the viewer service of the logger recording this run. */
    public DistributedLiveNetwork(String name, DistributedControl control, NetworkDeployment deployment,
                                  Optional<String> loggerViewerAddress) {
        super(name, control);
        this.control = control;
        this.deployment = deployment;
        this.loggerViewerAddress = loggerViewerAddress;
    }

    @Override
    public Optional<String> loggerViewerAddress() {
        return loggerViewerAddress;
    }

    @Override
    public NetworkInfo snapshot() {
        return control.snapshot();
    }

    @Override
    public Set<String> loadedModules() {
        return new LinkedHashSet<>(deployment.plan().loaded());
    }

    @Override
    public Set<String> heldModules() {
        held.retainAll(deployment.plan().loaded()); // an unloaded module is no longer on hold
        return Set.copyOf(held);
    }

    @Override
    public ChangeOutcome hold(String module) {
        ChangeOutcome o = super.hold(module);
        if (o.executed()) {
            held.add(module);
        }
        return o;
    }

    @Override
    public ChangeOutcome resume(String module) {
        ChangeOutcome o = super.resume(module);
        if (o.executed()) {
            held.remove(module);
        }
        return o;
    }

    @Override
    protected SampledNetwork sampled() {
        return this;
    }

    // ---------------------------------------------------------------- SampledNetwork

    @Override
    public void addChangeListener(ChangeListener listener) {
        control.addChangeListener(listener);
    }

    @Override
    public void removeChangeListener(ChangeListener listener) {
        control.removeChangeListener(listener);
    }

    @Override
    public Value value(NodeRef data) {
        String home = control.homeOf(data);
        Host host = home == null ? null : deployment.host(home);
        if (host == null) {
            return null;
        }
        try {
            Value now = ValueCodec.decodeRuntime(host.read(IdlMapping.id(data)));
            Value before = lastRead.get(data);
            if (before != null && before.samePayload(now)) {
                return before;
            }
            lastRead.put(data, now);
            return now;
        } catch (org.omg.CORBA.UserException | SystemException e) {
            return null; // no value yet, or its host is away: nothing to report this time
        }
    }

    @Override
    public List<NodeRef> runningDatas() {
        return datasOf(snapshot(), loadedModules());
    }

}
