package org.fdnet.corba;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.netinfo.NodeRef;

/**
 * An engine's events as {@code --trace} lines, with node names instead of ids: the one wording for a run on one host
 * ({@code org.fdnet.run.TracePrinter}) and for each host's trace of a distributed run ({@link HostTrace}).
 * It learns names from {@link NodeNamedEvent}s; thread-safe.
 */
public final class TraceText {
    private final Map<Integer, NodeRef> names = new ConcurrentHashMap<>();

    /** Remembers the name a {@link NodeNamedEvent} gives; other events are ignored. Cheap: for the hot path. */
    public void learn(NetworkEvent event) {
        if (event instanceof NodeNamedEvent n) {
            names.put(n.sourceId(), n.name());
        }
    }

    /** The event as one line, e.g. {@code value main/Map = [0.5, ...]} or {@code relation main/Survey RUNNING}. */
    public String of(NetworkEvent event) {
        learn(event);
        if (event instanceof NodeNamedEvent n) {
            return "named    #" + n.sourceId() + " " + n.kind().label() + " " + n.name();
        } else if (event instanceof DataValueEvent v) {
            return "value    " + name(v.sourceId()) + " = " + v.value().text();
        } else if (event instanceof RelationValueEvent r) {
            return "relation " + name(r.sourceId()) + " " + r.value();
        }
        NetworkCommandEvent c = (NetworkCommandEvent) event;
        return "command  " + c.command().text() + " " + c.paramsType() + " " + c.paramsId()
                + " by " + (c.sourceId() == 0 ? "controller" : name(c.sourceId()));
    }

    private String name(int id) {
        NodeRef ref = names.get(id);
        return ref == null ? "#" + id : ref.toString();
    }
}
