package org.fdnet.runtime;

import java.util.List;
import java.util.Set;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * The one surface through which the CLI, the editor and the distribution layer act on a running network.
 *
 * <p>Structural requests (edits, parameters, modules, restarts) are <em>change requests</em>: each is
 * applied atomically when it is safe — Relations already computing finish their firing — and settles as
 * {@link ChangeOutcome executed} or {@link ChangeOutcome failed} with the reason; a failed request leaves
 * the network exactly as it was. Every settled request is also told to the {@link ChangeListener}s.
 * All methods are thread-safe; a Relation may call them (through its Servants) from {@code compute}.
 */
public interface Controller extends NetworkControl {
    /** Applies an edit of the definition and makes the running network match it. */
    ChangeOutcome apply(String description, NetworkEdit edit);

    /** Sets one parameter of a node; a Relation restarts with it, a Data re-reads it keeping its value. */
    ChangeOutcome setParameter(NodeRef node, String name, String value);

    /** Loads a module that is not running (its nodes are created and its connections made). */
    ChangeOutcome load(String module);

    /** Unloads a module: its nodes leave, connections to them are dropped and come back when it returns. */
    ChangeOutcome unload(String module);

    /** Pauses a loaded module's Relations without deleting anything (the thesis's "on hold"). */
    ChangeOutcome hold(String module);

    /** Lets a held module's Relations fire again; one that missed an input fires once at once. */
    ChangeOutcome resume(String module);

    /**
     * A fresh instance of a Relation (e.g. after it FAILED), with the same definition.
     *
     * @param relation the Relation's module and name
     * @return executed, or failed when it is not a Relation running here
     */
    ChangeOutcome restart(NodeRef relation);

    /**
     * Writes a value into a local Data from outside (the user, a test, a distribution layer feeding a
     * stand-in). Converted to the Data's type.
     *
     * @param data  the Data's module and name
     * @param value the value; its readers fire as for any write
     * @throws IllegalArgumentException naming the Data when it is not running here or the value does not fit
     */
    void setValue(NodeRef data, Value value);

    /**
     * {@link #setValue(NodeRef, Value)} from text in the Data's own type ({@code 0.5}, {@code 1,2,3}, ...).
     *
     * @param data the Data's module and name
     * @param text the value's text form ({@link Value#parse})
     * @throws IllegalArgumentException naming the Data when it is not running here or the text does not fit
     */
    void setValue(NodeRef data, String text);

    /** {@link #setValue(NodeRef, String)} as a change request: refused with the reason instead of thrown. */
    @Override
    default ChangeOutcome send(NodeRef data, String text) {
        String description = "send " + data + "=" + text;
        try {
            setValue(data, text);
            return ChangeOutcome.executed(description);
        } catch (IllegalArgumentException e) {
            return ChangeOutcome.failed(description, e.getMessage());
        }
    }

    /**
     * The Data's current value, or {@code null} when it is not running here.
     *
     * @param data the Data's module and name
     * @return its latest committed value, or null
     */
    Value value(NodeRef data);

    /**
     * Subscribes to every value of a Data, in order; close the handle to stop. The subscription holds while the
     * Data's module is unloaded and sees the values again when it returns.
     *
     * @param data     the Data's module and name
     * @param observer called under the commit lock for each value: enqueue and return
     * @return the handle that ends the subscription
     * @throws IllegalArgumentException when the network defines no such Data
     */
    AutoCloseable observe(NodeRef data, DataValueObserver observer);

    /**
     * The state of a running Relation, or {@code null} when it is not running here.
     *
     * @param relation the Relation's module and name
     * @return its status, failure cause, missing inputs and firing count, or null
     */
    RelationState relationState(NodeRef relation);

    /**
     * Every running Relation's state, in definition order.
     *
     * @return a new list
     */
    List<RelationState> relationStates();

    /**
     * The id events carry for {@code node} (stable for the whole run), or -1 if it never ran here.
     *
     * @param node the node's module and name
     * @return its id, or -1
     */
    int nodeId(NodeRef node);

    /**
     * The modules running now.
     *
     * @return their names, {@code main} included
     */
    Set<String> loadedModules();

    /**
     * The loaded modules whose Relations are on hold.
     *
     * @return their names
     */
    Set<String> heldModules();

    /**
     * Connections with one end on another host (see {@link Placement}).
     *
     * @return every such connection of the running network, broken ones included
     */
    List<RemoteLink> remoteLinks();

    /**
     * The running network as a definition, including every node and connection it built itself, ready
     * to save as {@code .fdn}. A copy: editing it changes nothing.
     *
     * @return a new copy of the definition
     */
    NetworkInfo snapshot();

    /**
     * Tells {@code listener} of every change request from now on, after it settled.
     *
     * @param listener the listener; it must not block
     */
    void addChangeListener(ChangeListener listener);

    /**
     * Stops telling {@code listener}.
     *
     * @param listener a listener added before; any other is ignored
     */
    void removeChangeListener(ChangeListener listener);
}
