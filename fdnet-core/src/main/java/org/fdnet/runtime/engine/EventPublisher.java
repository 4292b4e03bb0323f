package org.fdnet.runtime.engine;

import java.util.Arrays;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.EventClock;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Value;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Turns what the engine does into {@link NetworkEvent}s stamped by the network's one {@link EventClock},
 * and hands them to the sinks. With no sink attached nothing is built. A Data's event carries the value's own
 * {@link org.fdnet.event.TypedValue} (shared, immutable): inside the commit lock one event object is made and
 * nothing is formatted — text, where anyone needs it, is made outside (the logger's COPY, a trace).
 */
final class EventPublisher {
    private static final Logger LOG = LoggerFactory.getLogger(EventPublisher.class);
    /** The controller's source id; nodes count from 1. */
    static final int CONTROLLER = 0;

    private final EventClock clock;
    private volatile EventSink[] sinks = new EventSink[0];

    EventPublisher(EventClock clock) {
        this.clock = clock;
    }

    EventClock clock() {
        return clock;
    }

    synchronized void add(EventSink sink) {
        EventSink[] next = Arrays.copyOf(sinks, sinks.length + 1);
        next[sinks.length] = sink;
        sinks = next;
    }

    synchronized void remove(EventSink sink) {
        sinks = Arrays.stream(sinks).filter(s -> s != sink).toArray(EventSink[]::new);
    }

    boolean enabled() {
        return sinks.length > 0;
    }

    /** Called under the commit lock, with the value's own (already unique) time. */
    void dataValue(DataNode data, Value stamped) {
        if (enabled()) {
            emit(new DataValueEvent(data.id, stamped.time(), stamped.typed())); // the value's own payload: no text
        }
    }

    void relationValue(int relationId, String text) {
        if (enabled()) {
            emit(new RelationValueEvent(relationId, clock.next(), text));
        }
    }

    void command(int sourceId, NetworkCommand command, String paramsId, String paramsType) {
        if (enabled()) {
            String sourceType = sourceId == CONTROLLER ? "controller" : "proc";
            emit(new NetworkCommandEvent(sourceId, clock.next(), sourceType, command, paramsId, paramsType));
        }
    }

    void named(int id, NodeKind kind, NodeRef ref) {
        if (enabled()) {
            emit(new NodeNamedEvent(id, clock.next(), kind, ref));
        }
    }

    private void emit(NetworkEvent event) {
        for (EventSink sink : sinks) {
            try {
                sink.accept(event);
            } catch (RuntimeException e) {
                LOG.warn("event sink {} failed on {}; it keeps receiving", sink, event, e);
            }
        }
    }

    void flush() {
        for (EventSink sink : sinks) {
            try {
                sink.flush();
            } catch (RuntimeException e) {
                LOG.warn("event sink {} failed to flush", sink, e);
            }
        }
    }
}
