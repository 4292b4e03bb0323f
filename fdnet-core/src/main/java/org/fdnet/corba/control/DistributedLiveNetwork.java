package org.fdnet.corba.control;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.fdnet.control.LiveNetwork;
import org.fdnet.control.LiveNetworkListener;
import org.fdnet.control.LiveSubscriptions;
import org.fdnet.control.SampledNetwork;
import org.fdnet.corba.DeploymentPlan;
import org.fdnet.corba.DistributedControl;
import org.fdnet.corba.IdlMapping;
import org.fdnet.corba.NetworkDeployment;
import org.fdnet.corba.ValueCodec;
import org.fdnet.corba.idl.Host;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeListener;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkEdit;
import org.fdnet.runtime.Value;
import org.omg.CORBA.SystemException;

/**
 * A {@link LiveNetwork} of a run across hosts, over its two-phase {@link DistributedControl}: every change settled
 * there — the control object's, {@code fdnet run}'s standard-input commands, a Relation's Servants on any host — is
 * told to subscribers. The snapshot is the running definition, including what Relations built through Paste. Values
 * are sampled by reading each running Data from its home host ({@code Host.read}) ten times a second; a Data is
 * reported when its value differs from the previous sample.
 */
public final class DistributedLiveNetwork implements LiveNetwork, SampledNetwork {
    private final String name;
    private final DistributedControl control;
    private final NetworkDeployment deployment;
    private final Set<String> held = ConcurrentHashMap.newKeySet();
    private final LiveSubscriptions subscriptions;
    private final Map<NodeRef, Value> lastRead = new ConcurrentHashMap<>();

    public DistributedLiveNetwork(String name, DistributedControl control, NetworkDeployment deployment) {
        this.name = name;
        this.control = control;
        this.deployment = deployment;
        this.subscriptions = new LiveSubscriptions(name, this);
    }

    @Override
    public String name() {
        return name;
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
        ChangeOutcome o = control.hold(module);
        if (o.executed()) {
            held.add(module);
        }
        return o;
    }

    @Override
    public ChangeOutcome resume(String module) {
        ChangeOutcome o = control.resume(module);
        if (o.executed()) {
            held.remove(module);
        }
        return o;
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
        return subscriptions.open(listener);
    }

    /** Tells every subscriber that the run stopped, their last call. */
    public void networkStopped(String reason) {
        subscriptions.networkStopped(reason);
    }

    @Override
    public void close() {
        subscriptions.closeAll();
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
        String home = homeOf(data);
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
        List<NodeRef> datas = new ArrayList<>();
        NetworkInfo now = snapshot();
        Set<String> loaded = loadedModules();
        for (ModuleInfo m : now.modules()) {
            if (loaded.contains(m.name())) {
                for (NodeInfo n : m.nodes()) {
                    if (n.kind() == NodeKind.DATA) {
                        datas.add(new NodeRef(m.name(), n.name()));
                    }
                }
            }
        }
        return datas;
    }

    private String homeOf(NodeRef data) {
        DeploymentPlan plan = deployment.plan();
        for (String h : plan.hosts()) {
            for (DeploymentPlan.Placed p : plan.shareOf(h).nodes()) {
                if (p.ref().equals(data)) {
                    return h;
                }
            }
        }
        return null;
    }
}
