package org.fdnet.corba.control;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import org.fdnet.control.LiveNetwork;
import org.fdnet.control.LiveNetworkListener;
import org.fdnet.control.LiveSubscription;
import org.fdnet.control.NetworkDiff;
import org.fdnet.control.SampledNetwork;
import org.fdnet.corba.DeploymentPlan;
import org.fdnet.corba.IdlMapping;
import org.fdnet.corba.NetworkDeployment;
import org.fdnet.corba.ValueCodec;
import org.fdnet.corba.idl.Host;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeListener;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkControl;
import org.fdnet.runtime.NetworkEdit;
import org.fdnet.runtime.Value;
import org.omg.CORBA.SystemException;

/**
 * A {@link LiveNetwork} of a run across hosts: changes go to the run's {@link NetworkControl} (the two-phase
 * {@code DistributedControl}); every change made through this object — the control object's, and {@code fdnet run}'s
 * standard-input commands — is told to subscribers once it settled. Values are sampled by reading each running Data
 * from its home host ({@code Host.read}) ten times a second; a Data is reported when its value differs from the
 * previous sample.
 *
 * <p>The snapshot is the deployed definition with the edits executed through this object. Changes the hosts make by
 * themselves (a Relation's Servants) are not seen here: across hosts each host's Servants see its own share.
 */
public final class DistributedLiveNetwork implements LiveNetwork, SampledNetwork {
    private final String name;
    private final NetworkControl control;
    private final NetworkDeployment deployment;
    private NetworkInfo definition;
    private final Set<String> held = ConcurrentHashMap.newKeySet();
    private final List<ChangeListener> changeListeners = new CopyOnWriteArrayList<>();
    private final List<LiveSubscription> subscriptions = new CopyOnWriteArrayList<>();
    private final Map<NodeRef, Value> lastRead = new ConcurrentHashMap<>();

    public DistributedLiveNetwork(String name, NetworkInfo definition, NetworkControl control,
                                  NetworkDeployment deployment) {
        this.name = name;
        this.definition = definition.copy();
        this.control = control;
        this.deployment = deployment;
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public synchronized NetworkInfo snapshot() {
        return definition.copy();
    }

    @Override
    public Set<String> loadedModules() {
        Set<String> loaded = new LinkedHashSet<>();
        DeploymentPlan plan = deployment.plan();
        for (String h : plan.hosts()) {
            loaded.addAll(plan.shareOf(h).modules());
        }
        return loaded;
    }

    @Override
    public Set<String> heldModules() {
        return Set.copyOf(held);
    }

    @Override
    public ChangeOutcome apply(String description, NetworkInfo base, NetworkInfo edited) {
        return apply(description, NetworkDiff.between(base, edited).asEdit());
    }

    @Override
    public ChangeOutcome apply(String description, NetworkEdit edit) {
        ChangeOutcome o = control.apply(description, edit);
        if (o.executed()) {
            synchronized (this) {
                NetworkInfo next = definition.copy();
                try {
                    edit.applyTo(next);
                    definition = next;
                } catch (EditRefusedException e) {
                    // the hosts executed it; the copy here could not follow: keep the deployed definition
                    org.slf4j.LoggerFactory.getLogger(DistributedLiveNetwork.class)
                            .warn("{}: executed {}, but the snapshot could not follow: {}", name, description,
                                    e.getMessage());
                }
            }
        }
        return settled(o);
    }

    @Override
    public ChangeOutcome load(String module) {
        return settled(control.load(module));
    }

    @Override
    public ChangeOutcome unload(String module) {
        return settled(control.unload(module));
    }

    @Override
    public ChangeOutcome hold(String module) {
        ChangeOutcome o = control.hold(module);
        if (o.executed()) {
            held.add(module);
        }
        return settled(o);
    }

    @Override
    public ChangeOutcome resume(String module) {
        ChangeOutcome o = control.resume(module);
        if (o.executed()) {
            held.remove(module);
        }
        return settled(o);
    }

    @Override
    public ChangeOutcome setParameter(NodeRef node, String parameter, String value) {
        return settled(control.setParameter(node, parameter, value));
    }

    @Override
    public ChangeOutcome send(NodeRef data, String text) {
        return settled(control.send(data, text));
    }

    private ChangeOutcome settled(ChangeOutcome o) {
        for (ChangeListener l : changeListeners) {
            l.changeSettled(o);
        }
        return o;
    }

    @Override
    public AutoCloseable subscribe(LiveNetworkListener listener) {
        LiveSubscription s = new LiveSubscription(name, this, listener, subscriptions::remove);
        subscriptions.add(s);
        s.start();
        return s;
    }

    /** Tells every subscriber that the run stopped, their last call. */
    public void networkStopped(String reason) {
        for (LiveSubscription s : subscriptions) {
            s.disconnect(reason);
        }
    }

    @Override
    public void close() {
        for (LiveSubscription s : subscriptions) {
            s.close();
        }
    }

    // ---------------------------------------------------------------- SampledNetwork

    @Override
    public void addChangeListener(ChangeListener listener) {
        changeListeners.add(listener);
    }

    @Override
    public void removeChangeListener(ChangeListener listener) {
        changeListeners.remove(listener);
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
