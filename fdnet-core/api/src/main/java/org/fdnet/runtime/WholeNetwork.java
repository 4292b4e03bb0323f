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
        /**
         * Whether the node ran somewhere at that moment.
         *
         * @param node the node's module and name
         * @return true when a host runs it
         */
        public boolean running(NodeRef node) {
            return placedOn.containsKey(node);
        }
    }

    /**
     * The whole network now, gathered from every host.
     *
     * @return one consistent view
     * @throws IllegalStateException when it cannot be had, saying why (e.g. a host does not answer)
     */
    Snapshot snapshot();

    /**
     * A running Data's current value, read on its own host; {@code null} before its first or when not running.
     *
     * @param data the Data's module and name
     * @return its value, or null
     */
    Value value(NodeRef data);

    /**
     * Applies an edit of the whole definition on every host it touches, all or nothing.
     *
     * @param description what the change does, for its events and its outcome
     * @param edit        the edit of the definition
     * @return executed, or failed with the reason (no host changed then)
     */
    ChangeOutcome apply(String description, NetworkEdit edit);

    /**
     * Loads a module on every host that runs part of it.
     *
     * @param module the module's name
     * @return executed, or failed with the reason (no host changed then)
     */
    ChangeOutcome load(String module);

    /**
     * Unloads a module on every host that runs part of it.
     *
     * @param module the module's name
     * @return executed, or failed with the reason (no host changed then)
     */
    ChangeOutcome unload(String module);

    /**
     * Pauses a module's Relations on every host.
     *
     * @param module the module's name
     * @return executed, or failed with the reason (no host changed then)
     */
    ChangeOutcome hold(String module);

    /**
     * Lets a held module's Relations fire again on every host.
     *
     * @param module the module's name
     * @return executed, or failed with the reason (no host changed then)
     */
    ChangeOutcome resume(String module);

    /**
     * The answer of the servant at {@code path} on whichever host has one (asked through the network's coordinator).
     *
     * @param path     the servant's path, e.g. {@code arm/planner}
     * @param message  what to do, as the servant understands it
     * @param argument the message's argument
     * @return the servant's reply
     * @throws MessageRefusedException when no host has a servant there, it refused, or a host does not answer
     */
    default Value message(String path, String message, Value argument) {
        throw new MessageRefusedException("no servant at " + path + ": this view of the network reaches no other host's servants");
    }
}
