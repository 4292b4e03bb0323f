package org.fdnet.runtime.servant;

import org.fdnet.netinfo.LinkedConnection;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkEdit;

/**
 * What the Servants read and change: this engine alone ({@link EngineScope}), or the whole network over every
 * host ({@link WholeNetworkScope}). Each query takes one {@link WholeNetwork.Snapshot} and answers from it, so a
 * Visitor's search reads the network once.
 */
interface ServantScope {
    WholeNetwork.Snapshot snapshot();

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
