package org.fdnet.event;

import java.util.ArrayList;
import java.util.List;

/** Keeps every event in memory, in arrival order: for tests and for {@code fdnet run}'s summary. */
public final class MemoryEventSink implements EventSink {
    private final List<NetworkEvent> events = new ArrayList<>();

    @Override
    public synchronized void accept(NetworkEvent event) {
        events.add(event);
    }

    /**
     * A copy of what arrived so far.
     *
     * @return a new list, in arrival order
     */
    public synchronized List<NetworkEvent> events() {
        return new ArrayList<>(events);
    }

    /**
     * The events of one type that arrived so far.
     *
     * @param <T>  the event type
     * @param type e.g. {@code DataValueEvent.class}
     * @return a new list, in arrival order
     */
    public synchronized <T extends NetworkEvent> List<T> events(Class<T> type) {
        List<T> result = new ArrayList<>();
        for (NetworkEvent e : events) {
            if (type.isInstance(e)) {
                result.add(type.cast(e));
            }
        }
        return result;
    }

    /**
     * How many events arrived.
     *
     * @return the count so far
     */
    public synchronized int size() {
        return events.size();
    }
}
