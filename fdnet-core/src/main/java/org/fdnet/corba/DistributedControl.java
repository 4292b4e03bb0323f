package org.fdnet.corba;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import org.fdnet.corba.idl.ChangeOp;
import org.fdnet.corba.idl.ChangeRequest;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.ModuleConnection;
import org.fdnet.corba.idl.NetworkDescription;
import org.fdnet.corba.idl.NodeId;
import org.fdnet.corba.idl.NodeSpec;
import org.fdnet.corba.idl.Refused;
import org.fdnet.corba.idl.ShareChange;
import org.fdnet.corba.idl.StandInSpec;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.ModuleTree;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeListener;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkControl;
import org.fdnet.runtime.NetworkEdit;
import org.fdnet.runtime.WholeNetwork;
import org.omg.CORBA.SystemException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@link NetworkControl} of a distributed network: each change goes to every host it touches in two phases.
 *
 * <pre>
 *   hold Gait ─▶ hosts whose share has module Gait (DeploymentPlan)
 *      phase 1: host.prepareChange(c) on each ── any refusal or dead host ─▶ abortChange on the prepared; refused
 *      phase 2: host.commitChange(c.id) on each ─▶ executed (or: executed on A, failed on B with the reason)
 *
 *   load M / unload M / apply(edit) / a Relation's Paste on any host (through NetworkCoordinator)
 *      next definition + loaded modules ─▶ DeploymentPlan.next ─▶ PlanDifference (per host, links)
 *      phase 1: prepareShareChange on each host whose share changes (classes allowed there? names free?)
 *      phase 2: close the links that go ─▶ commitChange on each ─▶ open the new links ─▶ the new plan is watched
 * </pre>
 *
 * A module is held or resumed on every host with a node of it; a parameter is set, and a value sent, on the
 * node's own host. A structural change is derived from the whole definition before and after it, so whatever an
 * edit does — nodes, connections, modules — each host gets exactly its part, with the stand-ins and links it needs.
 */
public final class DistributedControl implements NetworkControl {
    private static final Logger LOG = LoggerFactory.getLogger(DistributedControl.class);
    private static final AtomicLong NEXT_ID = new AtomicLong(System.currentTimeMillis() * 1000);

    private final NetworkDeployment deployment;
    /** Changes with every executed structural change; written under the deployment's change lock, after the plan. */
    private volatile long version = 1;

    private final List<ChangeListener> listeners = new CopyOnWriteArrayList<>();

    public DistributedControl(NetworkDeployment deployment) {
        this.deployment = deployment;
    }

    /** Told of every change request once it settled, whoever made it: an operator, a tool, a Relation's Servants. */
    public void addChangeListener(ChangeListener listener) {
        listeners.add(listener);
    }

    public void removeChangeListener(ChangeListener listener) {
        listeners.remove(listener);
    }

    private ChangeOutcome told(ChangeOutcome outcome) {
        for (ChangeListener l : listeners) {
            l.changeSettled(outcome);
        }
        return outcome;
    }

    /** The running definition, including what Relations built through Paste (a copy: editing it changes nothing). */
    public NetworkInfo snapshot() {
        return deployment.plan().definition();
    }

    /** The whole network now: definition, loaded modules and where each running node runs. */
    public WholeNetwork.Snapshot wholeSnapshot() {
        return snapshotOf(deployment.plan());
    }

    private static WholeNetwork.Snapshot snapshotOf(DeploymentPlan plan) {
        return new WholeNetwork.Snapshot(plan.definition(), plan.loaded(), plan.placement());
    }

    /**
     * The whole network as the IDL describes it, with the version a later {@link #applyDefinition} names. Takes no
     * lock (a Relation asks it in the middle of changes): the version is read before the plan, so a description can
     * only pair a newer plan with an older version, and an edit made on it is refused, never misapplied.
     */
    NetworkDescription description() {
        long v = version;
        return NetworkDescriptions.encode(v, snapshotOf(deployment.plan()));
    }

    /** The host a running node runs on, or {@code null}. */
    public String homeOf(NodeRef node) {
        return deployment.plan().placement().get(node);
    }

    NetworkDeployment deployment() {
        return deployment;
    }

    @Override
    public ChangeOutcome apply(String description, NetworkEdit edit) {
        return told(deployment.changingShares(() -> applyNow(description, edit)));
    }

    private ChangeOutcome applyNow(String description, NetworkEdit edit) {
        DeploymentPlan plan = deployment.plan();
        NetworkInfo next = plan.definition();
        try {
            edit.applyTo(next);
        } catch (RuntimeException e) {
            return ChangeOutcome.failed(description, (e.getMessage() == null ? e.toString() : e.getMessage())
                    + "; nothing changed on any host");
        }
        return reshape(description, next, plan.loaded());
    }

    /**
     * Makes the running network match {@code after}, which the caller derived from the description of
     * {@code basedOn}; refused when the network changed since (the caller reads it again and retries).
     */
    ChangeOutcome applyDefinition(String description, long basedOn, NetworkInfo after) {
        return told(deployment.changingShares(() -> {
            if (basedOn != version) {
                return ChangeOutcome.failed(description, "the network changed since it was read (version " + basedOn
                        + ", now " + version + "); nothing changed on any host (try again)");
            }
            return reshape(description, after, deployment.plan().loaded());
        }));
    }

    @Override
    public ChangeOutcome load(String module) {
        return told(deployment.changingShares(() -> loadNow(module)));
    }

    private ChangeOutcome loadNow(String module) {
        String description = "load " + module;
        DeploymentPlan plan = deployment.plan();
        NetworkInfo def = plan.definition();
        String refused = ModuleTree.whyNotLoadable(def, plan.loaded(), module);
        if (refused != null) {
            return ChangeOutcome.failed(description, refused);
        }
        return reshape(description, def, ModuleTree.afterLoad(def, plan.loaded(), module));
    }

    @Override
    public ChangeOutcome unload(String module) {
        return told(deployment.changingShares(() -> unloadNow(module)));
    }

    private ChangeOutcome unloadNow(String module) {
        String description = "unload " + module;
        DeploymentPlan plan = deployment.plan();
        if (module.equals(ModuleInfo.MAIN)) {
            return ChangeOutcome.failed(description, "module main is always loaded");
        }
        if (!plan.loaded().contains(module)) {
            return ChangeOutcome.failed(description, "module " + module + " is not loaded");
        }
        return reshape(description, plan.definition(), ModuleTree.afterUnload(plan.loaded(), module));
    }

    @Override
    public ChangeOutcome hold(String module) {
        return told(onHostsOf(module, "hold " + module, request(ChangeOp.CO_HOLD, module, null, "", "")));
    }

    @Override
    public ChangeOutcome resume(String module) {
        return told(onHostsOf(module, "resume " + module, request(ChangeOp.CO_RESUME, module, null, "", "")));
    }

    @Override
    public ChangeOutcome setParameter(NodeRef node, String name, String value) {
        return told(onHomeOf(node, "set " + node + ":" + name + "=" + value,
                request(ChangeOp.CO_SET_PARAMETER, "", node, name, value)));
    }

    @Override
    public ChangeOutcome send(NodeRef data, String text) {
        return told(onHomeOf(data, "send " + data + "=" + text, request(ChangeOp.CO_SEND, "", data, "", text)));
    }

    private static ChangeRequest request(ChangeOp op, String module, NodeRef node, String name, String value) {
        NodeId id = node == null ? new NodeId("", "") : IdlMapping.id(node);
        return new ChangeRequest(NEXT_ID.incrementAndGet(), op, module, id, name, value);
    }

    private ChangeOutcome onHostsOf(String module, String description, ChangeRequest change) {
        DeploymentPlan plan = deployment.plan();
        List<String> hosts = plan.hosts().stream().filter(h -> plan.shareOf(h).modules().contains(module)).toList();
        if (hosts.isEmpty()) {
            return ChangeOutcome.failed(description, "module " + module + " runs on no host of this network");
        }
        return twoPhase(description, hosts, change.id, (name, host) -> host.prepareChange(change), () -> List.of());
    }

    private ChangeOutcome onHomeOf(NodeRef node, String description, ChangeRequest change) {
        String home = homeOf(node);
        if (home == null) {
            return ChangeOutcome.failed(description, "node " + node + " runs on no host of this network");
        }
        return twoPhase(description, List.of(home), change.id, (name, host) -> host.prepareChange(change),
                () -> List.of());
    }

    /** Derives every host's part of going to {@code next} with {@code loaded} running, and makes it everywhere. */
    private ChangeOutcome reshape(String description, NetworkInfo next, Set<String> loaded) {
        return deployment.changingShares(() -> reshapeShares(description, next, loaded));
    }

    private ChangeOutcome reshapeShares(String description, NetworkInfo next, Set<String> loaded) {
        DeploymentPlan before = deployment.plan();
        DeploymentPlan after = before.next(next, loaded);
        PlanDifference difference = PlanDifference.between(before, after);
        Set<String> touched = new LinkedHashSet<>(difference.hosts().keySet());
        for (DeploymentPlan.Link l : difference.opened()) {
            touched.add(l.fromHost());
            touched.add(l.toHost());
        }
        for (String name : touched) {
            if (deployment.lostHosts().contains(name)) {
                return ChangeOutcome.failed(description, "host " + name + " is lost (it is re-created when it comes"
                        + " back); nothing changed on any host");
            }
            if (deployment.join(name) == null) {
                return ChangeOutcome.failed(description, "host " + name + " is not running (start it with: fdnet host"
                        + " --name " + name + "); nothing changed on any host");
            }
        }
        if (difference.isEmpty()) {
            deployment.replacePlan(after);
            version++;
            return ChangeOutcome.executed(description + " (no running host is affected)");
        }
        long id = NEXT_ID.incrementAndGet();
        Map<String, ShareChange> parts = new LinkedHashMap<>();
        difference.hosts().forEach((name, change) -> parts.put(name, toIdl(id, change)));
        boolean[] committing = {false}; // set once every host prepared: from then on the hosts change
        ChangeOutcome outcome = twoPhase(description, List.copyOf(parts.keySet()), id,
                (name, host) -> host.prepareShareChange(parts.get(name)),
                () -> {
                    committing[0] = true;
                    difference.closed().forEach(deployment::closeLink);
                    return List.of();
                },
                () -> {
                    List<String> failed = new ArrayList<>();
                    for (DeploymentPlan.Link l : difference.opened()) {
                        try {
                            deployment.openLink(l);
                        } catch (DeploymentException e) {
                            failed.add(e.getMessage());
                        }
                    }
                    return failed;
                });
        if (committing[0]) {
            deployment.replacePlan(after); // executed, or executed in part: the hosts now run (most of) the new plan
            version++;
        }
        LOG.info("structural change {} (network version {})", outcome, version);
        return outcome;
    }

    private static ShareChange toIdl(long id, PlanDifference.HostChange c) {
        return new ShareChange(id,
                c.disconnect().stream().map(p -> new ModuleConnection(p.module(), IdlMapping.spec(p.connection())))
                        .toArray(ModuleConnection[]::new),
                c.destroy().stream().map(IdlMapping::id).toArray(NodeId[]::new),
                c.standIns().stream().map(s -> new StandInSpec(IdlMapping.spec(s.data().module(), s.node()), s.homeHost()))
                        .toArray(StandInSpec[]::new),
                c.create().stream().map(p -> IdlMapping.spec(p.module(), p.node())).toArray(NodeSpec[]::new),
                c.connect().stream().map(p -> new ModuleConnection(p.module(), IdlMapping.spec(p.connection())))
                        .toArray(ModuleConnection[]::new));
    }

    /** Phase one on one host: the reason it cannot execute the change, or "". */
    @FunctionalInterface
    private interface Prepare {
        String on(String name, Host host);
    }

    /** What runs around phase two; returns the failures it met. */
    @FunctionalInterface
    private interface Step {
        List<String> run();
    }

    private ChangeOutcome twoPhase(String description, List<String> hosts, long id, Prepare prepare,
                                   Step afterCommit) {
        return twoPhase(description, hosts, id, prepare, () -> List.of(), afterCommit);
    }

    /**
     * Prepare on every host; only when none refused: {@code beforeCommit}, commit on every host, {@code afterCommit};
     * else abort the prepared ones and change nothing.
     */
    private ChangeOutcome twoPhase(String description, List<String> hosts, long id, Prepare prepare,
                                   Step beforeCommit, Step afterCommit) {
        return deployment.changingShares(() -> twoPhaseNow(description, hosts, id, prepare, beforeCommit, afterCommit));
    }

    private ChangeOutcome twoPhaseNow(String description, List<String> hosts, long id, Prepare prepare,
                                      Step beforeCommit, Step afterCommit) {
        Map<String, Host> prepared = new LinkedHashMap<>();
        String refusal = null;
        for (String name : hosts) {
            Host host = deployment.host(name);
            try {
                String reason = host == null ? "host " + name + " is not connected" : prepare.on(name, host);
                if (!reason.isEmpty()) {
                    refusal = reason;
                    break;
                }
                prepared.put(name, host);
            } catch (SystemException e) {
                refusal = "host " + name + " does not answer (" + e.getClass().getSimpleName() + ")";
                break;
            }
        }
        if (refusal != null) {
            for (Map.Entry<String, Host> e : prepared.entrySet()) {
                try {
                    e.getValue().abortChange(id);
                } catch (SystemException gone) {
                    LOG.warn("could not abort change {} on host {}: {}", id, e.getKey(), gone.toString());
                }
            }
            return ChangeOutcome.failed(description, refusal + "; nothing changed on any host");
        }
        List<String> failed = new ArrayList<>(beforeCommit.run());
        List<String> done = new ArrayList<>();
        for (Map.Entry<String, Host> e : prepared.entrySet()) {
            try {
                e.getValue().commitChange(id);
                done.add(e.getKey());
            } catch (Refused r) {
                failed.add(r.reason);
            } catch (SystemException gone) {
                failed.add("host " + e.getKey() + " does not answer (" + gone.getClass().getSimpleName() + ")");
            }
        }
        failed.addAll(afterCommit.run());
        if (failed.isEmpty()) {
            return ChangeOutcome.executed(description + " on " + (done.isEmpty() ? "no host (links only)"
                    : String.join(", ", done)));
        }
        return ChangeOutcome.failed(description, "executed on " + (done.isEmpty() ? "no host" : String.join(", ", done))
                + ", failed: " + String.join("; ", failed));
    }
}
