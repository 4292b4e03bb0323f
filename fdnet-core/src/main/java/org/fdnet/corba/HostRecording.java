package org.fdnet.corba;

import java.util.Arrays;
import java.util.function.Predicate;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RunIdentity;
import org.fdnet.event.client.CommitReport;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.netinfo.NodeRef;

/**
 * A host's recording of one network run: every event of the host's engine goes to a {@link LoggerClient} filed
 * under that run as this host, except those of stand-ins. A stand-in is a shadow of a Data whose home host
 * records it; recording the shadow too would show the Data twice, once as a node of a host it does not live on.
 * A stand-in is known by name when the engine names it ({@link NodeNamedEvent}); its later events are dropped by
 * id.
 */
final class HostRecording implements EventSink {
    private final LoggerClient client;
    private final Predicate<NodeRef> standIn;
    private volatile boolean[] dropped = new boolean[0]; // by node id; copied on the (rare) write

    HostRecording(LoggerClient client, Predicate<NodeRef> standIn) {
        this.client = client;
        this.standIn = standIn;
    }

    RunIdentity run() {
        return client.networkRun();
    }

    LoggerClient client() {
        return client;
    }

    @Override
    public void accept(NetworkEvent event) {
        if (event instanceof NodeNamedEvent named && standIn.test(named.name())) {
            drop(named.sourceId());
            return;
        }
        boolean[] d = dropped;
        int id = event.sourceId();
        if (id >= 0 && id < d.length && d[id]) {
            return;
        }
        client.accept(event);
    }

    private synchronized void drop(int id) {
        if (id < 0) {
            return;
        }
        boolean[] d = Arrays.copyOf(dropped, Math.max(dropped.length, id + 1));
        d[id] = true;
        dropped = d;
    }

    @Override
    public void flush() {
        client.flush();
    }

    /** Ends the recording: closes the client (bounded: it waits for the logger's commits at most its flush timeout); what it committed. */
    String end() {
        client.close();
        return CommitReport.of(client);
    }
}
