package org.fdnet.runtime;

import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.Locale;
import java.util.Set;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * Decides which nodes this process instantiates (the distribution seam). A node that is not local is
 * run by another host: a local Relation that reads or writes a non-local Data gets a local
 * <em>stand-in</em> of it (see {@link RemoteLink}), which the distribution layer feeds and observes.
 */
@FunctionalInterface
public interface Placement {
    /**
     * Whether this process runs {@code node}.
     *
     * @param ref  the node's module and name
     * @param node its definition, whose {@code host} usually decides
     * @return true to instantiate it here, false to leave it to another host
     */
    boolean isLocal(NodeRef ref, NodeInfo node);

    /**
     * Every node runs here: {@code fdnet run} on one machine. The default.
     *
     * @return a placement that keeps every node
     */
    static Placement all() {
        return (ref, node) -> true;
    }

    /**
     * Nodes whose host is localhost, 127.0.0.1, ::1, empty, or this machine's name.
     *
     * @return a placement for this machine, by {@link #localNames()}
     */
    static Placement thisHost() {
        return forHostNames(localNames());
    }

    /**
     * Nodes whose host is one of {@code names} (compared without case) or a loopback name.
     *
     * @param names the host names this process answers to
     * @return a placement that keeps nodes of those hosts, of a loopback name or of no host
     */
    static Placement forHostNames(Set<String> names) {
        Set<String> lower = names.stream().map(n -> n.toLowerCase(Locale.ROOT)).collect(java.util.stream.Collectors.toSet());
        return (ref, node) -> {
            String host = node.host().strip().toLowerCase(Locale.ROOT);
            return host.isEmpty() || host.equals("localhost") || host.equals("127.0.0.1") || host.equals("::1")
                    || lower.contains(host);
        };
    }

    /**
     * This machine's host name and canonical name, as far as the resolver knows them.
     *
     * @return the names, empty when the resolver does not know this machine
     */
    static Set<String> localNames() {
        try {
            InetAddress local = InetAddress.getLocalHost();
            return Set.of(local.getHostName(), local.getCanonicalHostName()).stream()
                    .collect(java.util.stream.Collectors.toSet());
        } catch (UnknownHostException e) {
            return Set.of();
        }
    }
}
