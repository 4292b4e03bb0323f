package org.fdnet.corba;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.ModuleTree;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * Where every node of the loaded modules runs and what crosses hosts. Pure computation, no I/O.
 *
 * <p>A node runs on the host its {@code host} element names; {@code localhost}, {@code 127.0.0.1},
 * {@code ::1}, an empty host and this machine's names mean the coordinating process's own host. A
 * connection whose Data and Relation share a host is made on that host (direct, in memory). Otherwise
 * the Relation's host gets a stand-in of the Data, the connection is made there against the stand-in,
 * and a link carries values: Data home → stand-in for a Reader, stand-in → Data home for a Writer. Links
 * are shared: one per Data, direction and pair of hosts.
 */
public final class DeploymentPlan {

    /** A node placed on a host. */
    public record Placed(String module, NodeInfo node) {
        public NodeRef ref() {
            return new NodeRef(module, node.name());
        }
    }

    /** A connection made on a host, with the module that declares it. */
    public record PlacedConnection(String module, ConnectionInfo connection) {
    }

    /** A stand-in of {@code data} on a host; the Data itself lives on {@code homeHost}. */
    public record StandIn(NodeRef data, NodeInfo node, String homeHost) {
    }

    /**
     * Values of {@code data} flow from its instance on {@code fromHost} to its instance on {@code toHost}.
     * {@code fromDataHome}: a Reader's link, from the Data itself; else a Writer's, into the Data.
     */
    public record Link(long id, NodeRef data, String fromHost, String toHost, boolean fromDataHome) {
        @Override
        public String toString() {
            return fromHost + ":" + data + " -> " + toHost + " (link " + id + ")";
        }
    }

    /** What one host runs. */
    public static final class HostShare {
        final List<Placed> nodes = new ArrayList<>();
        final Map<NodeRef, StandIn> standIns = new LinkedHashMap<>();
        final List<PlacedConnection> connections = new ArrayList<>();

        public List<Placed> nodes() {
            return nodes;
        }

        public List<StandIn> standIns() {
            return List.copyOf(standIns.values());
        }

        public List<PlacedConnection> connections() {
            return connections;
        }

        /** Modules with nodes or connections on this host, in network order. */
        public List<String> modules() {
            Set<String> m = new LinkedHashSet<>();
            nodes.forEach(p -> m.add(p.module()));
            connections.forEach(c -> m.add(c.module()));
            return List.copyOf(m);
        }
    }

    private final Map<String, HostShare> shares = new LinkedHashMap<>();
    private final List<Link> links = new ArrayList<>();
    private final NetworkInfo definition;
    private final Set<String> loaded;
    private final String localHost;
    private final Set<String> localNames;
    private long lastLinkId;

    private DeploymentPlan(NetworkInfo definition, Set<String> loaded, String localHost, Set<String> localNames) {
        this.definition = definition;
        this.loaded = loaded;
        this.localHost = localHost;
        this.localNames = localNames;
    }

    /** Plans the modules of {@code network} that are loaded at start. */
    public static DeploymentPlan of(NetworkInfo network, String localHost, Set<String> localNames) {
        return of(network, localHost, localNames, Set.of());
    }

    /**
     * Plans {@code main}, the modules loaded at start and {@code alsoLoaded}.
     *
     * @param localHost  the name the coordinating process's own host has
     * @param localNames names that mean "this machine" besides the loopback names
     * @throws IllegalArgumentException naming a module of {@code alsoLoaded} the network does not have
     */
    public static DeploymentPlan of(NetworkInfo network, String localHost, Set<String> localNames,
                                    Set<String> alsoLoaded) {
        for (String m : alsoLoaded) {
            if (network.module(m) == null) {
                throw new IllegalArgumentException("the network has no module named '" + m + "'");
            }
        }
        Set<String> loaded = ModuleTree.atStart(network);
        for (String m : alsoLoaded) {
            loaded = ModuleTree.afterLoad(network, loaded, m);
        }
        Set<String> local = new LinkedHashSet<>();
        localNames.forEach(n -> local.add(n.toLowerCase(Locale.ROOT)));
        return plan(network.copy(), loaded, localHost, Set.copyOf(local), null);
    }

    /**
     * The plan of the same deployment after a structural change: {@code next} (the whole definition) with exactly
     * the modules {@code loaded} running ({@code main} always). A link that stays keeps its id; a new one gets an
     * id this deployment never used, so a host never confuses it with one that was closed.
     */
    public DeploymentPlan next(NetworkInfo next, Set<String> loaded) {
        Set<String> running = new LinkedHashSet<>();
        running.add(ModuleInfo.MAIN);
        for (String m : loaded) {
            if (next.module(m) != null) {
                running.add(m);
            }
        }
        return plan(next.copy(), running, localHost, localNames, this);
    }

    private static DeploymentPlan plan(NetworkInfo network, Set<String> loaded, String localHost,
                                       Set<String> localLowerCase, DeploymentPlan previous) {
        DeploymentPlan plan = new DeploymentPlan(network, Set.copyOf(loaded), localHost, localLowerCase);
        Map<NodeRef, String> hostOf = new LinkedHashMap<>();
        for (ModuleInfo m : network.modules()) {
            if (!loaded.contains(m.name())) {
                continue;
            }
            for (NodeInfo n : m.nodes()) {
                String host = placeOf(n.host(), localHost, localLowerCase);
                hostOf.put(new NodeRef(m.name(), n.name()), host);
                plan.share(host).nodes.add(new Placed(m.name(), n));
            }
        }
        Map<String, Long> previousIds = new LinkedHashMap<>();
        if (previous != null) {
            previous.links.forEach(l -> previousIds.put(l.fromHost() + "|" + l.toHost() + "|" + l.data(), l.id()));
            plan.lastLinkId = previous.lastLinkId;
        }
        Map<String, Link> linkByKey = new LinkedHashMap<>();
        for (ModuleInfo m : network.modules()) {
            for (ConnectionInfo c : m.connections()) {
                String dataHost = hostOf.get(c.data());
                String relationHost = hostOf.get(c.relation());
                if (!c.exists() || dataHost == null || relationHost == null) {
                    continue; // not made at start, or an end's module is not loaded
                }
                plan.share(relationHost).connections.add(new PlacedConnection(m.name(), c));
                if (dataHost.equals(relationHost)) {
                    continue;
                }
                plan.share(relationHost).standIns.putIfAbsent(c.data(),
                        new StandIn(c.data(), network.node(c.data()), dataHost));
                String from = c.kind() == ConnectionKind.READER ? dataHost : relationHost;
                String to = c.kind() == ConnectionKind.READER ? relationHost : dataHost;
                String key = from + "|" + to + "|" + c.data();
                if (!linkByKey.containsKey(key)) {
                    Long kept = previousIds.get(key);
                    long id = kept != null ? kept : ++plan.lastLinkId;
                    linkByKey.put(key, new Link(id, c.data(), from, to, from.equals(dataHost)));
                }
            }
        }
        plan.links.addAll(linkByKey.values());
        return plan;
    }

    /** The whole definition this plan places (a copy: editing it changes nothing). */
    public NetworkInfo definition() {
        return definition.copy();
    }

    /** The modules running under this plan. */
    public Set<String> loaded() {
        return loaded;
    }

    /** The host each running node runs on. */
    public Map<NodeRef, String> placement() {
        Map<NodeRef, String> placed = new LinkedHashMap<>();
        shares.forEach((host, share) -> share.nodes.forEach(p -> placed.put(p.ref(), host)));
        return placed;
    }

    /** The host a node's {@code host} element means. */
    public static String placeOf(String declared, String localHost, Set<String> localNamesLowerCase) {
        String h = declared.strip();
        String lower = h.toLowerCase(Locale.ROOT);
        if (h.isEmpty() || lower.equals("localhost") || lower.equals("127.0.0.1") || lower.equals("::1")
                || localNamesLowerCase.contains(lower)) {
            return localHost;
        }
        return h;
    }

    private HostShare share(String host) {
        return shares.computeIfAbsent(host, h -> new HostShare());
    }

    /** Hosts in first-use order. */
    public Set<String> hosts() {
        return shares.keySet();
    }

    /** What {@code host} runs (empty when nothing is placed there). */
    public HostShare shareOf(String host) {
        return shares.getOrDefault(host, new HostShare());
    }

    /**
     * Every link, those out of a Data's home first: a value a Writer's link brings into a Data must find
     * the Reader links out of it already open, or the Readers elsewhere would miss it.
     */
    public List<Link> links() {
        return links.stream().sorted(OPENING_ORDER).toList();
    }

    /** The links with an end on {@code host}, in opening order. */
    public List<Link> linksTouching(String host) {
        return links().stream().filter(l -> l.fromHost.equals(host) || l.toHost.equals(host)).toList();
    }

    private static final Comparator<Link> OPENING_ORDER =
            Comparator.comparing((Link l) -> !l.fromDataHome()).thenComparingLong(Link::id);
}
