package org.fdnet.corba;

import java.util.Arrays;
import java.util.function.Predicate;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.netinfo.NodeRef;

/**
 * Tells a host's stand-ins' events from its own. A stand-in is a shadow of a Data that lives on another host, which
 * records and traces it; shown here too, the Data would appear twice, once as a node of a host it does not live on.
 * A stand-in is known by name when the engine names it ({@link NodeNamedEvent}); its later events by id.
 */
final class StandInEvents {
    private final Predicate<NodeRef> standIn;
    private volatile boolean[] ofStandIn = new boolean[0]; // by node id; copied on the (rare) write

    StandInEvents(Predicate<NodeRef> standIn) {
        this.standIn = standIn;
    }

    /** Whether {@code event} is a stand-in's (its naming included); called on the engine's hot path. */
    boolean test(NetworkEvent event) {
        if (event instanceof NodeNamedEvent named && standIn.test(named.name())) {
            mark(named.sourceId());
            return true;
        }
        boolean[] marked = ofStandIn;
        int id = event.sourceId();
        return id >= 0 && id < marked.length && marked[id];
    }

    private synchronized void mark(int id) {
        if (id < 0) {
            return;
        }
        boolean[] marked = Arrays.copyOf(ofStandIn, Math.max(ofStandIn.length, id + 1));
        marked[id] = true;
        ofStandIn = marked;
    }
}
