package org.fdnet.corba;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.UUID;
import org.fdnet.event.RunIdentity;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.NetworkEdit;
import org.fdnet.runtime.ServantRegistry;
import org.fdnet.runtime.WholeNetwork;

/**
 * What a host needs from the engine that runs its share of a network: the seam between CORBA
 * ({@link HostServant}) and the single-host runtime. Every method may be called from any ORB thread.
 *
 * <p>Values written locally reach observers with origin {@code null}; values that arrive over a link
 * are {@linkplain #inject injected} with the host they came from as origin, so a link never sends a
 * value back where it came from.
 */
public interface LocalNetwork {

    /** Instantiates {@code node} as {@code ref}; the host has already checked that its class is allowed. */
    void create(NodeRef ref, NodeInfo node);

    /**
     * Creates {@code nodes} of {@code module} and makes {@code connections} (declared in that module) as
     * one change: a Relation starts with its connections in place. All or nothing.
     */
    default void load(String module, List<NodeInfo> nodes, List<ConnectionInfo> connections) {
        List<NodeRef> created = new ArrayList<>();
        try {
            for (NodeInfo n : nodes) {
                NodeRef ref = new NodeRef(module, n.name());
                create(ref, n);
                created.add(ref);
            }
            connections.forEach(this::connect);
        } catch (RuntimeException e) {
            created.forEach(this::destroy);
            throw e;
        }
    }

    /** Creates the local shadow of a Data that lives on another host; it holds values, loads no class. */
    void createStandIn(NodeRef ref, NodeInfo node);

    /** @throws java.util.NoSuchElementException when there is no such node */
    void destroy(NodeRef ref);

    /** The nodes running here, stand-ins included. */
    List<NodeRef> nodes();

    /** Whether {@code ref} is declared here: running, or a stand-in waiting for a local connection. */
    boolean knows(NodeRef ref);

    /** Joins two local nodes (either may be a stand-in). */
    void connect(ConnectionInfo connection);

    void disconnect(ConnectionInfo connection);

    /** The Data's current value, or {@code null} before its first. */
    Object read(NodeRef data);

    /** A write from outside the network (an operator, a test): observers see origin {@code null}. */
    void write(NodeRef data, Object value);

    /**
     * A value that arrived over a link from {@code originHost}, having entered the links at {@code origin}:
     * set it and tell observers in order. Observers see both with this value only, never with values
     * written because of it.
     */
    void inject(NodeRef data, Object value, String originHost, ValueOrigin origin);

    /** Tells {@code observer} every value of {@code data} from now on, in order; close to stop. */
    AutoCloseable observe(NodeRef data, ValueObserver observer);

    /**
     * Records this host's events as its part of the network run {@code run}, with the logger at {@code hostPort}
     * (or the host's own), this host's clock being {@code clockOffsetMicros} ahead of the coordinator's;
     * {@code false} when nothing is recorded or {@code run} already is.
     *
     * @throws UnsupportedOperationException when this engine has no events to record
     * @throws IllegalArgumentException when {@code hostPort} is not {@code HOST:PORT}
     */
    default boolean recordRun(String hostPort, RunIdentity run, long clockOffsetMicros) {
        throw new UnsupportedOperationException("this host's engine (" + getClass().getSimpleName()
                + ") records no events");
    }

    /** Ends the recording of {@code run}: what the logger committed, or empty when this host does not record it. */
    default Optional<String> endRun(UUID run) {
        return Optional.empty();
    }

    /**
     * Runs {@code workers} worker threads from now on (the run being deployed asked for them), or this host's own
     * default when {@code workers} is 0; how many run now.
     *
     * @throws IllegalArgumentException when {@code workers} is below 0 or above this host's limit
     * @throws UnsupportedOperationException when this engine cannot be sized and {@code workers} is not 0
     */
    default int sizeEngine(int workers) {
        if (workers == 0) {
            return 0; // its own, whatever that is: an engine without a pool is not asked for one
        }
        throw new UnsupportedOperationException("this host's engine (" + getClass().getSimpleName()
                + ") has no worker threads to size");
    }

    /**
     * Keeps up to {@code capacity} of this host's own events of {@code run} for {@link #takeTrace}; a trace of another
     * run ends.
     *
     * @throws IllegalArgumentException when {@code capacity} is out of range
     * @throws UnsupportedOperationException when this engine has no events to trace
     */
    default void traceRun(UUID run, int capacity) {
        throw new UnsupportedOperationException("this host's engine (" + getClass().getSimpleName()
                + ") has no events to trace");
    }

    /** At most {@code max} kept events of {@code run}, oldest first; empty when this host does not trace it. */
    default HostTrace.Batch takeTrace(UUID run, int max) {
        return HostTrace.Batch.EMPTY;
    }

    /** Stops keeping events of {@code run}. */
    default void endTrace(UUID run) {
    }

    /** {@code ref} is about to be declared as a stand-in (a shadow of a Data homed on another host). */
    default void expectStandIn(NodeRef ref) {
    }

    /**
     * Why {@code edit} of this host's definition cannot be made now (names taken, ends missing), or {@code null};
     * changes nothing.
     */
    default String check(String description, NetworkEdit edit) {
        return "this host's engine (" + getClass().getSimpleName() + ") takes no structural changes";
    }

    /**
     * Makes {@code edit} of this host's definition as one change of the engine; the modules it names are loaded.
     *
     * @throws IllegalStateException with the engine's reason when it refuses; nothing changed then
     */
    default void reshape(String description, NetworkEdit edit) {
        throw new IllegalStateException(check(description, edit));
    }

    /** From now on this host's Relations' Servants see and reshape {@code whole}; ignored by engines without them. */
    default void seeWholeNetwork(WholeNetwork whole) {
    }

    /** The engine's servant tree, through which other hosts' Relations message this host's servants; empty without. */
    default Optional<ServantRegistry> servants() {
        return Optional.empty();
    }

    /**
     * The engine's controller, through which live changes (hold, resume, parameters, values as text) are
     * executed here; empty when this engine takes no live changes.
     */
    default Optional<Controller> controller() {
        return Optional.empty();
    }

    /**
     * Receives every value of one Data on the thread that set it; must not block for long. A value injected
     * from a link comes with the host it came from and where it entered the links; a value written on this
     * host (by an operator or a Relation) with {@code null} for both.
     */
    @FunctionalInterface
    interface ValueObserver {
        void onValue(Object value, String originHost, ValueOrigin origin);
    }
}
