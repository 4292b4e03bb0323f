package org.fdnet.runtime;

import org.fdnet.netinfo.NodeRef;

/**
 * The live changes an operator makes to a running network, wherever it runs: the facade {@code fdnet run}'s
 * standard-input commands call, and the one Part 8 publishes as the editor's CORBA control object.
 *
 * <p>Each change is executed everywhere it applies or refused with its reason, changing nothing. One host:
 * the engine's {@link Controller} is a {@code NetworkControl}. Several hosts:
 * {@code org.fdnet.corba.DistributedControl} prepares the change on every host it touches and commits it
 * only when none refused.
 */
public interface NetworkControl {
    /** Applies an edit of the definition and makes the running network match it, on every host it touches. */
    ChangeOutcome apply(String description, NetworkEdit edit);

    /** Loads a module that is not running. */
    ChangeOutcome load(String module);

    /** Unloads a running module. */
    ChangeOutcome unload(String module);

    /** Pauses a loaded module's Relations (the thesis's "on hold"). */
    ChangeOutcome hold(String module);

    /** Lets a held module's Relations fire again. */
    ChangeOutcome resume(String module);

    /** Sets one parameter of a node. */
    ChangeOutcome setParameter(NodeRef node, String name, String value);

    /** Writes {@code text}, in the Data's own type ({@code 0.5}, {@code 1,2,3}, ...), into a running Data. */
    ChangeOutcome send(NodeRef data, String text);
}
