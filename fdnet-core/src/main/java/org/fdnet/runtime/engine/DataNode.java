package org.fdnet.runtime.engine;

import java.util.Arrays;
import org.fdnet.event.ValueType;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Data;
import org.fdnet.runtime.DataValueObserver;
import org.fdnet.runtime.NodeLifecycle;
import org.fdnet.runtime.Value;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The engine's side of a Data: the author's {@link Data} instance, its latest value, the Relations that
 * read it and the observers. The value is one immutable {@link Value} behind a volatile field, replaced
 * whole under the commit lock: a reader always sees a complete value.
 */
final class DataNode implements Data.DataPort {
    private static final Logger LOG = LoggerFactory.getLogger(DataNode.class);
    static final RelationNode[] NO_READERS = new RelationNode[0];
    private static final DataValueObserver[] NO_OBSERVERS = new DataValueObserver[0];

    final int id;
    final NodeRef ref;
    final NodeInfo info;
    final Data data;
    final ValueType type;
    /** A local stand-in for a Data that lives on another host. */
    final boolean standIn;
    private final Dataflow flow;

    volatile Value value;
    volatile RelationNode[] readers = NO_READERS;
    private volatile DataValueObserver[] observers = NO_OBSERVERS;
    volatile boolean alive = true;

    DataNode(int id, NodeRef ref, NodeInfo info, Data data, boolean standIn, Dataflow flow) {
        this.id = id;
        this.ref = ref;
        this.info = info;
        this.data = data;
        this.type = data.type();
        this.standIn = standIn;
        this.flow = flow;
    }

    /** Converts and lets the Data check a value before it is committed; throws naming this Data. */
    Value prepare(Value proposed) {
        try {
            Value converted = proposed.convertTo(type);
            Value accepted = NodeLifecycle.accept(data, converted);
            if (accepted == null || accepted.type() != type) {
                throw new IllegalArgumentException(data.getClass().getName() + ".accept returned "
                        + (accepted == null ? "null" : "a " + accepted.type() + " value"));
            }
            return accepted.withTick(proposed.tick()); // a Data that reshapes a value keeps where it came from
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("writing " + ref + " (" + type.name().toLowerCase() + "): "
                    + e.getMessage(), e);
        }
    }

    /** Called under the commit lock with a stamped value. */
    void store(Value stamped) {
        value = stamped;
        for (DataValueObserver o : observers) {
            try {
                o.valueChanged(ref, id, stamped);
            } catch (RuntimeException e) {
                LOG.warn("value observer {} of {} failed", o, ref, e);
            }
        }
    }

    synchronized void addObserver(DataValueObserver o) {
        DataValueObserver[] next = Arrays.copyOf(observers, observers.length + 1);
        next[observers.length] = o;
        observers = next;
    }

    synchronized void removeObserver(DataValueObserver o) {
        observers = Arrays.stream(observers).filter(x -> x != o).toArray(DataValueObserver[]::new);
    }

    Dataflow flow() {
        return flow;
    }

    @Override
    public Value current() {
        return value;
    }

    @Override
    public void publish(Value v) {
        if (!alive) {
            LOG.debug("{} left the network; a pushed value is ignored", ref);
            return;
        }
        flow.write(this, v, null);
    }

    @Override
    public void publishTogether(Data.DataPort[] ports, Value[] values) {
        PushTogether.commit(ports, values);
    }

    @Override
    public String toString() {
        return ref + "#" + id;
    }
}
