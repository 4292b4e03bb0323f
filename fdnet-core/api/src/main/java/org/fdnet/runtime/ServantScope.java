package org.fdnet.runtime;

import java.util.function.Function;
import org.fdnet.netinfo.LinkedConnection;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * What the Servants read and change: this engine alone ({@code engine.EngineScope}), or the whole network over every
 * host ({@code engine.WholeNetworkScope}). Each query takes one {@link WholeNetwork.Snapshot} and answers from it, so
 * a Visitor's search reads the network once. The engine implements it; node authors never do.
 */
public interface ServantScope {
    /**
     * The network as the scope sees it now.
     *
     * @return the definition, the loaded modules and where each running node runs
     */
    WholeNetwork.Snapshot snapshot();

    /**
     * Answers {@code query} from the definition now, without a copy where it can (one engine reads under its lock).
     *
     * @param <T>   what the query returns
     * @param query reads the definition and must not change it or keep it
     * @return the query's answer
     */
    <T> T read(Function<NetworkInfo, T> query);

    /**
     * One node's description now, or {@code null} when the network defines no such node.
     *
     * @param ref the node's module and name
     * @return its description, or null
     */
    NodeDescription describe(NodeRef ref);

    /**
     * The node's description in {@code snapshot}, or {@code null} when it defines no such node.
     *
     * @param snapshot a snapshot of this scope
     * @param ref      the node's module and name
     * @return its description, or null
     */
    NodeDescription describe(WholeNetwork.Snapshot snapshot, NodeRef ref);

    /**
     * Whether both ends of the connection run and it is active.
     *
     * @param snapshot   a snapshot of this scope
     * @param connection a connection of the snapshot's definition
     * @return true when values can flow through it
     */
    boolean live(WholeNetwork.Snapshot snapshot, LinkedConnection connection);

    /**
     * Applies an edit as a change request ({@link NetworkControl#apply}).
     *
     * @param description what the change does
     * @param edit        the edit of the definition
     * @return executed, or failed with the reason
     */
    ChangeOutcome apply(String description, NetworkEdit edit);

    /**
     * Loads a module ({@link NetworkControl#load}).
     *
     * @param module the module's name
     * @return executed, or failed with the reason
     */
    ChangeOutcome load(String module);

    /**
     * Unloads a module ({@link NetworkControl#unload}).
     *
     * @param module the module's name
     * @return executed, or failed with the reason
     */
    ChangeOutcome unload(String module);

    /**
     * Puts a module on hold ({@link NetworkControl#hold}).
     *
     * @param module the module's name
     * @return executed, or failed with the reason
     */
    ChangeOutcome hold(String module);

    /**
     * Resumes a held module ({@link NetworkControl#resume}).
     *
     * @param module the module's name
     * @return executed, or failed with the reason
     */
    ChangeOutcome resume(String module);
}
