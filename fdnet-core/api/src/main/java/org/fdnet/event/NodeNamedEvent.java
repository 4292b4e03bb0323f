package org.fdnet.event;

import java.util.Objects;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * Tells event consumers which node an id stands for. A core emits it for every node before the
 * node's first other event, so a logger can resolve ids to {@code Module/Node} names.
 *
 * @param sourceId the node's id
 * @param time     when the id was given, µs since the epoch
 * @param kind     Data or Relation
 * @param name     the node's module and name
 */
public record NodeNamedEvent(int sourceId, long time, NodeKind kind, NodeRef name) implements NetworkEvent {
    /**
     * Checks the parts.
     *
     * @param sourceId the node's id
     * @param time     when the id was given, µs since the epoch
     * @param kind     Data or Relation, not null
     * @param name     the node's module and name, not null
     */
    public NodeNamedEvent {
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(name, "name");
    }
}
