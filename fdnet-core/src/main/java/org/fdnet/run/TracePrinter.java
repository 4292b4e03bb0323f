package org.fdnet.run;

import java.io.PrintWriter;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.netinfo.NodeRef;

/** {@code fdnet run --trace}: prints every event as it happens, with node names instead of ids. */
final class TracePrinter implements EventSink {
    private final PrintWriter out;
    private final Map<Integer, NodeRef> names = new ConcurrentHashMap<>();
    private final long start;

    TracePrinter(PrintWriter out, long startMicros) {
        this.out = out;
        this.start = startMicros;
    }

    @Override
    public void accept(NetworkEvent event) {
        String when = String.format(java.util.Locale.ROOT, "%10.6f", (event.time() - start) / 1e6);
        String line;
        if (event instanceof NodeNamedEvent n) {
            names.put(n.sourceId(), n.name());
            line = "named    #" + n.sourceId() + " " + n.kind().label() + " " + n.name();
        } else if (event instanceof DataValueEvent v) {
            line = "value    " + name(v.sourceId()) + " = " + v.value().text();
        } else if (event instanceof RelationValueEvent r) {
            line = "relation " + name(r.sourceId()) + " " + r.value();
        } else {
            NetworkCommandEvent c = (NetworkCommandEvent) event;
            line = "command  " + c.command().text() + " " + c.paramsType() + " " + c.paramsId()
                    + " by " + (c.sourceId() == 0 ? "controller" : name(c.sourceId()));
        }
        synchronized (out) {
            out.println("trace " + when + " " + line);
        }
    }

    private String name(int id) {
        NodeRef ref = names.get(id);
        return ref == null ? "#" + id : ref.toString();
    }

    @Override
    public void flush() {
        synchronized (out) {
            out.flush();
        }
    }
}
