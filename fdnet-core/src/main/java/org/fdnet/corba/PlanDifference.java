package org.fdnet.corba;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import org.fdnet.netinfo.NodeRef;

/**
 * What must change on each host, and which links close and open, to go from one {@link DeploymentPlan} of a
 * running network to the next (after an edit, a paste, a module loaded or unloaded). Pure computation, no I/O.
 *
 * <p>A node whose definition changed is destroyed and created again; so are the connections and links that touch
 * it. Per host, the change is executed in this order: disconnect, destroy, stand-ins, create, connect.
 */
final class PlanDifference {

    /** One host's part of the change. */
    record HostChange(String host, List<DeploymentPlan.PlacedConnection> disconnect, List<NodeRef> destroy,
                      List<DeploymentPlan.StandIn> standIns, List<DeploymentPlan.Placed> create,
                      List<DeploymentPlan.PlacedConnection> connect) {
        boolean isEmpty() {
            return disconnect.isEmpty() && destroy.isEmpty() && standIns.isEmpty() && create.isEmpty()
                    && connect.isEmpty();
        }
    }

    private final Map<String, HostChange> hosts;
    private final List<DeploymentPlan.Link> closed;
    private final List<DeploymentPlan.Link> opened;

    private PlanDifference(Map<String, HostChange> hosts, List<DeploymentPlan.Link> closed,
                           List<DeploymentPlan.Link> opened) {
        this.hosts = hosts;
        this.closed = closed;
        this.opened = opened;
    }

    static PlanDifference between(DeploymentPlan before, DeploymentPlan after) {
        Set<String> names = new LinkedHashSet<>(before.hosts());
        names.addAll(after.hosts());
        Map<String, HostChange> changes = new LinkedHashMap<>();
        Map<String, Set<NodeRef>> recreated = new LinkedHashMap<>();
        for (String host : names) {
            DeploymentPlan.HostShare was = before.shareOf(host);
            DeploymentPlan.HostShare is = after.shareOf(host);
            Map<NodeRef, DeploymentPlan.Placed> wasNodes = byRef(was.nodes());
            Map<NodeRef, DeploymentPlan.Placed> isNodes = byRef(is.nodes());
            Map<NodeRef, DeploymentPlan.StandIn> wasStandIns = standIns(was);
            Map<NodeRef, DeploymentPlan.StandIn> isStandIns = standIns(is);

            List<NodeRef> destroy = new ArrayList<>();
            List<DeploymentPlan.Placed> create = new ArrayList<>();
            wasNodes.forEach((ref, p) -> {
                DeploymentPlan.Placed next = isNodes.get(ref);
                if (next == null || !next.node().equals(p.node())) {
                    destroy.add(ref);
                }
            });
            isNodes.forEach((ref, p) -> {
                DeploymentPlan.Placed old = wasNodes.get(ref);
                if (old == null || !old.node().equals(p.node())) {
                    create.add(p);
                }
            });
            List<DeploymentPlan.StandIn> standIns = new ArrayList<>();
            wasStandIns.forEach((ref, s) -> {
                if (!Objects.equals(isStandIns.get(ref), s)) {
                    destroy.add(ref);
                }
            });
            isStandIns.forEach((ref, s) -> {
                if (!Objects.equals(wasStandIns.get(ref), s)) {
                    standIns.add(s);
                }
            });
            Set<NodeRef> gone = new LinkedHashSet<>(destroy);
            recreated.put(host, gone);
            List<DeploymentPlan.PlacedConnection> disconnect = new ArrayList<>();
            for (DeploymentPlan.PlacedConnection c : was.connections()) {
                // a connection touching a destroyed node goes with it
                if (!is.connections().contains(c) && !touches(c, gone)) {
                    disconnect.add(c);
                }
            }
            List<DeploymentPlan.PlacedConnection> connect = new ArrayList<>();
            for (DeploymentPlan.PlacedConnection c : is.connections()) {
                if (!was.connections().contains(c) || touches(c, gone)) {
                    connect.add(c);
                }
            }
            HostChange change = new HostChange(host, disconnect, destroy, standIns, create, connect);
            if (!change.isEmpty()) {
                changes.put(host, change);
            }
        }
        Map<Long, DeploymentPlan.Link> wasLinks = new LinkedHashMap<>();
        before.links().forEach(l -> wasLinks.put(l.id(), l));
        Map<Long, DeploymentPlan.Link> isLinks = new LinkedHashMap<>();
        after.links().forEach(l -> isLinks.put(l.id(), l));
        List<DeploymentPlan.Link> closed = new ArrayList<>();
        List<DeploymentPlan.Link> opened = new ArrayList<>();
        for (DeploymentPlan.Link l : before.links()) {
            if (!isLinks.containsKey(l.id()) || endRecreated(l, recreated)) {
                closed.add(l);
            }
        }
        for (DeploymentPlan.Link l : after.links()) {
            if (!wasLinks.containsKey(l.id()) || endRecreated(l, recreated)) {
                opened.add(l);
            }
        }
        return new PlanDifference(changes, closed, opened);
    }

    private static boolean endRecreated(DeploymentPlan.Link l, Map<String, Set<NodeRef>> recreated) {
        return recreated.getOrDefault(l.fromHost(), Set.of()).contains(l.data())
                || recreated.getOrDefault(l.toHost(), Set.of()).contains(l.data());
    }

    private static boolean touches(DeploymentPlan.PlacedConnection c, Set<NodeRef> nodes) {
        return nodes.contains(c.connection().data()) || nodes.contains(c.connection().relation());
    }

    private static Map<NodeRef, DeploymentPlan.Placed> byRef(List<DeploymentPlan.Placed> placed) {
        Map<NodeRef, DeploymentPlan.Placed> m = new LinkedHashMap<>();
        placed.forEach(p -> m.put(p.ref(), p));
        return m;
    }

    private static Map<NodeRef, DeploymentPlan.StandIn> standIns(DeploymentPlan.HostShare share) {
        Map<NodeRef, DeploymentPlan.StandIn> m = new LinkedHashMap<>();
        share.standIns().forEach(s -> m.put(s.data(), s));
        return m;
    }

    /** The hosts whose share changes, with their part, in plan order. */
    Map<String, HostChange> hosts() {
        return hosts;
    }

    /** Links to close before the hosts change (gone, or an end is re-created). */
    List<DeploymentPlan.Link> closed() {
        return closed;
    }

    /** Links to open once the hosts changed, in opening order (out of a Data's home first). */
    List<DeploymentPlan.Link> opened() {
        return opened;
    }

    boolean isEmpty() {
        return hosts.isEmpty() && closed.isEmpty() && opened.isEmpty();
    }
}
