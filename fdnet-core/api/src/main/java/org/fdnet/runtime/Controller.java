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

    /** A fresh instance of a Relation (e.g. after it FAILED), with the same definition. */
    ChangeOutcome restart(NodeRef relation);

    /**
     * Writes a value into a local Data from outside (the user, a test, a distribution layer feeding a
     * stand-in). Converted to the Data's type.
     *
     * @throws IllegalArgumentException naming the Data when it is not running here or the value does not fit
     */
    void setValue(NodeRef data, Value value);

    /** {@link #setValue(NodeRef, Value)} from text in the Data's own type ({@code 0.5}, {@code 1,2,3}, ...). */
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

    /** The Data's current value, or {@code null} when it is not running here. */
    Value value(NodeRef data);

    /** Subscribes to every value of a running Data, in order; close the handle to stop. */
    AutoCloseable observe(NodeRef data, DataValueObserver observer);

    /** The state of a running Relation, or {@code null} when it is not running here. */
    RelationState relationState(NodeRef relation);

    /** Every running Relation's state, in definition order. */
    List<RelationState> relationStates();

    /** The id events carry for {@code node} (stable for the whole run), or -1 if it never ran here. */
    int nodeId(NodeRef node);

    Set<String> loadedModules();

    Set<String> heldModules();

    /** Connections with one end on another host (see {@link Placement}). */
    List<RemoteLink> remoteLinks();

    /**
     * The running network as a definition, including every node and connection it built itself, ready
     * to save as {@code .fdn}. A copy: editing it changes nothing.
     */
    NetworkInfo snapshot();

    void addChangeListener(ChangeListener listener);

    void removeChangeListener(ChangeListener listener);
}
