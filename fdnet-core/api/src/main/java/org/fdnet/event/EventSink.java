package org.fdnet.event;

/**
 * Where a running network's events go: an in-memory list for tests, the logger client in production.
 * {@link #accept} is called on the runtime's hot path: it must never block a Relation and never throw
 * for a full or absent consumer (a sink that cannot keep an event counts and reports the loss).
 */
public interface EventSink extends AutoCloseable {
    /**
     * Takes one event; called in each source's time order, possibly from several threads.
     *
     * @param event the event, never null
     */
    void accept(NetworkEvent event);

    /** Delivers or persists what is buffered; default: nothing is buffered. */
    default void flush() {
    }

    @Override
    default void close() {
    }

    /**
     * One sink feeding two, in that order.
     *
     * @param first  gets each event first
     * @param second gets it next
     * @return a sink whose {@code accept} and {@code flush} go to both; its {@code close} closes neither
     */
    static EventSink both(EventSink first, EventSink second) {
        return new EventSink() {
            @Override
            public void accept(NetworkEvent event) {
                first.accept(event);
                second.accept(event);
            }

            @Override
            public void flush() {
                first.flush();
                second.flush();
            }
        };
    }
}
