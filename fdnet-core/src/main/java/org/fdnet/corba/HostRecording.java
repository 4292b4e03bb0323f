package org.fdnet.corba;

import java.util.function.Predicate;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.RunIdentity;
import org.fdnet.event.client.CommitReport;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.netinfo.NodeRef;

/**
 * A host's recording of one network run: every event of the host's engine goes to a {@link LoggerClient} filed
 * under that run as this host, except those of stand-ins ({@link StandInEvents}: their Data's home host records
 * them).
 */
final class HostRecording implements EventSink {
    private final LoggerClient client;
    private final StandInEvents standIns;

    HostRecording(LoggerClient client, Predicate<NodeRef> standIn) {
        this.client = client;
        this.standIns = new StandInEvents(standIn);
    }

    RunIdentity run() {
        return client.networkRun();
    }

    LoggerClient client() {
        return client;
    }

    @Override
    public void accept(NetworkEvent event) {
        if (!standIns.test(event)) {
            client.accept(event);
        }
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
