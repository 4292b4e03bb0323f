package org.fdnet.event;

import java.util.Objects;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * Tells event consumers which node an id stands for. A core emits it for every node before the
 * node's first other event, so a logger can resolve ids to {@code Module/Node} names.
 */
public record NodeNamedEvent(int sourceId, long time, NodeKind kind, NodeRef name) implements NetworkEvent {
    public NodeNamedEvent {
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(name, "name");
    }
}
