package org.fdnet.event;

/**
 * Something that happened in a running network, as the logger stores it. Every event names its
 * source (a node id, unique within one run of one core) and a time in microseconds since the epoch
 * that is unique and strictly increasing per source: the logger's primary key is
 * {@code (sourceid, time)}, so two events of one source with one time would lose a value.
 */
public sealed interface NetworkEvent
        permits DataValueEvent, RelationValueEvent, NetworkCommandEvent, NodeNamedEvent {

    /**
     * The node (or, for commands, the node or controller) that produced the event.
     *
     * @return the node id, unique within one run of one core; 0 for the controller
     */
    int sourceId();

    /**
     * Microseconds since the epoch; strictly increasing per source (see {@link EventClock}).
     *
     * @return when it happened
     */
    long time();
}
