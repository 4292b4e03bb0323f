package org.fdnet.corba;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.fdnet.corba.idl.ChangeOp;
import org.fdnet.corba.idl.ChangeRequest;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.NodeId;
import org.fdnet.corba.idl.Refused;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkControl;
import org.fdnet.runtime.NetworkEdit;
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
 * </pre>
 *
 * A module is held or resumed on every host with a node of it; a parameter is set, and a value sent, on the
 * node's own host. Loading and unloading a module across hosts needs a new deployment plan and is refused
 * with that reason (the local run's {@link org.fdnet.runtime.Controller} does both).
 */
public final class DistributedControl implements NetworkControl {
    private static final Logger LOG = LoggerFactory.getLogger(DistributedControl.class);
    private static final AtomicLong NEXT_ID = new AtomicLong(System.currentTimeMillis() * 1000);

    private final NetworkDeployment deployment;

    public DistributedControl(NetworkDeployment deployment) {
        this.deployment = deployment;
    }

    @Override
    public ChangeOutcome apply(String description, NetworkEdit edit) {
        return ChangeOutcome.failed(description, "editing a running distributed network is not supported yet");
    }

    @Override
    public ChangeOutcome load(String module) {
        return ChangeOutcome.failed("load " + module, "loading a module into a running distributed network is not"
                + " supported: start the run with --load " + module);
    }

    @Override
    public ChangeOutcome unload(String module) {
        return ChangeOutcome.failed("unload " + module, "unloading a module of a running distributed network is not"
                + " supported: hold it instead (hold " + module + ")");
    }

    @Override
    public ChangeOutcome hold(String module) {
        return onHostsOf(module, "hold " + module, request(ChangeOp.CO_HOLD, module, null, "", ""));
    }

    @Override
    public ChangeOutcome resume(String module) {
        return onHostsOf(module, "resume " + module, request(ChangeOp.CO_RESUME, module, null, "", ""));
    }

    @Override
    public ChangeOutcome setParameter(NodeRef node, String name, String value) {
        return onHomeOf(node, "set " + node + ":" + name + "=" + value,
                request(ChangeOp.CO_SET_PARAMETER, "", node, name, value));
    }

    @Override
    public ChangeOutcome send(NodeRef data, String text) {
        return onHomeOf(data, "send " + data + "=" + text, request(ChangeOp.CO_SEND, "", data, "", text));
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
        return twoPhase(description, hosts, change);
    }

    private ChangeOutcome onHomeOf(NodeRef node, String description, ChangeRequest change) {
        DeploymentPlan plan = deployment.plan();
        List<String> home = plan.hosts().stream()
                .filter(h -> plan.shareOf(h).nodes().stream().anyMatch(p -> p.ref().equals(node))).toList();
        if (home.isEmpty()) {
            return ChangeOutcome.failed(description, "node " + node + " runs on no host of this network");
        }
        return twoPhase(description, home, change);
    }

    /** Prepare on every host; commit on every host only when none refused; else abort the prepared ones. */
    private synchronized ChangeOutcome twoPhase(String description, List<String> hosts, ChangeRequest change) {
        Map<String, Host> prepared = new LinkedHashMap<>();
        String refusal = null;
        for (String name : hosts) {
            Host host = deployment.host(name);
            try {
                String reason = host == null ? "host " + name + " is not connected" : host.prepareChange(change);
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
                    e.getValue().abortChange(change.id);
                } catch (SystemException gone) {
                    LOG.warn("could not abort change {} on host {}: {}", change.id, e.getKey(), gone.toString());
                }
            }
            return ChangeOutcome.failed(description, refusal + "; nothing changed on any host");
        }
        List<String> done = new ArrayList<>();
        List<String> failed = new ArrayList<>();
        for (Map.Entry<String, Host> e : prepared.entrySet()) {
            try {
                e.getValue().commitChange(change.id);
                done.add(e.getKey());
            } catch (Refused r) {
                failed.add(r.reason);
            } catch (SystemException gone) {
                failed.add("host " + e.getKey() + " does not answer (" + gone.getClass().getSimpleName() + ")");
            }
        }
        if (failed.isEmpty()) {
            return ChangeOutcome.executed(description + " on " + String.join(", ", done));
        }
        return ChangeOutcome.failed(description, "executed on " + (done.isEmpty() ? "no host" : String.join(", ", done))
                + ", failed: " + String.join("; ", failed));
    }
}
