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
    WholeNetwork.Snapshot snapshot();

    /** Answers {@code query} from the definition now, without a copy where it can (one engine reads under its lock). */
    <T> T read(Function<NetworkInfo, T> query);

    /** One node's description now, or {@code null} when the network defines no such node. */
    NodeDescription describe(NodeRef ref);

    /** The node's description in {@code snapshot}, or {@code null} when it defines no such node. */
    NodeDescription describe(WholeNetwork.Snapshot snapshot, NodeRef ref);

    /** Whether both ends of the connection run and it is active. */
    boolean live(WholeNetwork.Snapshot snapshot, LinkedConnection connection);

    ChangeOutcome apply(String description, NetworkEdit edit);

    ChangeOutcome load(String module);

    ChangeOutcome unload(String module);

    ChangeOutcome hold(String module);

    ChangeOutcome resume(String module);
}
