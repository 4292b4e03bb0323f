package org.fdnet.runtime;

import java.util.Map;
import java.util.Set;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * The whole of a network that runs over several hosts, as the Servants of one host's Relations see and reshape it.
 * The distribution layer installs one on each host's engine ({@code engine.RuntimeNetwork#seeWholeNetwork});
 * without one, Servants see their own engine only. Every call may cross the network: a snapshot that cannot be had
 * throws {@link IllegalStateException} with the reason; a change that cannot be made is refused with it.
 */
public interface WholeNetwork {

    /**
     * The whole network at one moment.
     *
     * @param definition every module, node and connection (a copy), each node naming the host it is declared on
     * @param loaded     the modules running now
     * @param placedOn   the host each running node runs on
     */
    record Snapshot(NetworkInfo definition, Set<String> loaded, Map<NodeRef, String> placedOn) {
        public boolean running(NodeRef node) {
            return placedOn.containsKey(node);
        }
    }

    Snapshot snapshot();

    /** A running Data's current value, read on its own host; {@code null} before its first or when not running. */
    Value value(NodeRef data);

    /** Applies an edit of the whole definition on every host it touches, all or nothing. */
    ChangeOutcome apply(String description, NetworkEdit edit);

    ChangeOutcome load(String module);

    ChangeOutcome unload(String module);

    ChangeOutcome hold(String module);

    ChangeOutcome resume(String module);

    /**
     * The answer of the servant at {@code path} on whichever host has one (asked through the network's coordinator).
     *
     * @throws MessageRefusedException when no host has a servant there, it refused, or a host does not answer
     */
    default Value message(String path, String message, Value argument) {
        throw new MessageRefusedException("no servant at " + path + ": this view of the network reaches no other host's servants");
    }
}
