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
    /**
     * Applies an edit of the definition and makes the running network match it, on every host it touches.
     *
     * @param description what the change does, e.g. {@code create main/Filter}: the outcome's and the events' text
     * @param edit        the edit of the definition ({@link NetworkEdits} has the common ones)
     * @return executed, or failed with the reason (nothing changed then)
     */
    ChangeOutcome apply(String description, NetworkEdit edit);

    /**
     * Loads a module that is not running.
     *
     * @param module the module's name
     * @return executed, or failed with the reason (e.g. no such module, already loaded)
     */
    ChangeOutcome load(String module);

    /**
     * Unloads a running module.
     *
     * @param module the module's name
     * @return executed, or failed with the reason (e.g. {@code main}, which is always loaded, or not loaded)
     */
    ChangeOutcome unload(String module);

    /**
     * Pauses a loaded module's Relations (the thesis's "on hold").
     *
     * @param module the module's name
     * @return executed, or failed with the reason (not loaded, already on hold)
     */
    ChangeOutcome hold(String module);

    /**
     * Lets a held module's Relations fire again.
     *
     * @param module the module's name
     * @return executed, or failed when the module is not on hold
     */
    ChangeOutcome resume(String module);

    /**
     * Sets one parameter of a node.
     *
     * @param node  the node's module and name
     * @param name  the parameter's name; one the node does not have yet is added
     * @param value the new text, checked against the parameter's declared type
     * @return executed, or failed with the reason (e.g. no such node, a value the node refuses)
     */
    ChangeOutcome setParameter(NodeRef node, String name, String value);

    /**
     * Writes {@code text}, in the Data's own type ({@code 0.5}, {@code 1,2,3}, ...), into a running Data.
     *
     * @param data the Data's module and name
     * @param text the value's text form ({@link Value#parse})
     * @return executed, or failed with the reason (not running, not a value of its type, refused by the Data)
     */
    ChangeOutcome send(NodeRef data, String text);
}
