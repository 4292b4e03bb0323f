package org.fdnet.logger.server;

import java.io.IOException;
import java.net.Socket;
import java.sql.SQLException;
import java.util.List;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.client.ResponsiveThreads;
import org.fdnet.event.wire.ErrorCode;
import org.fdnet.event.wire.EventCodec;
import org.fdnet.event.wire.Frame;
import org.fdnet.event.wire.FrameReader;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.Hello;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.event.wire.LoggedRun;
import org.fdnet.event.wire.MessageType;
import org.fdnet.event.wire.Protocol;
import org.fdnet.event.wire.ProtocolException;
import org.fdnet.event.wire.ViewerRequest;
import org.fdnet.logger.cache.CachedEvent;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A viewer's connection to the sender server: LIST_NODES (names), HISTORY (cache and database merged, sent
 * in chunks; values in binary, so a number costs 22 bytes and no formatting), MONITOR / UNMONITOR (live stream through a {@link MonitorStream}).
 */
final class SenderConnection extends Connection {
    private static final Logger LOG = LoggerFactory.getLogger(SenderConnection.class);

    private final ViewerService viewers;
    private final boolean realTime;
    private MonitorStream monitor;

    /** @param realTime whether to answer from a real-time thread ({@link ResponsiveThreads}; {@code priority.enabled}) */
    SenderConnection(Socket socket, int maxFrameBytes, ViewerService viewers, boolean realTime) {
        super(socket, maxFrameBytes);
        this.viewers = viewers;
        this.realTime = realTime;
    }

    @Override
    protected String describe() {
        return super.describe(); // visible to MonitorStream (same package)
    }

    @Override
    protected boolean handshake(Hello hello) throws IOException {
        if (hello.role() != Protocol.ROLE_VIEWER) {
            throw new ProtocolException("the sender server serves viewers; use the receiver port for cores");
        }
        send(w -> w.begin(MessageType.WELCOME).putShort(Protocol.VERSION).putLong(0));
        return true;
    }

    @Override
    protected void serve(FrameReader in) throws IOException {
        if (realTime) {
            ResponsiveThreads.raiseCurrent("the logger's sender thread for " + describe());
        }
        Frame f;
        while ((f = in.read()) != null) {
            frames++;
            ViewerRequest r = ViewerRequest.read(f);
            switch (r.type()) {
                case LIST_NODES -> listNodes(r.id(), r.filter());
                case LIST_RUNS -> listRuns(r.id());
                case HISTORY -> history(r.id(), r.nodes(), r.from(), r.to());
                case MONITOR -> monitor().monitor(r.nodes());
                case UNMONITOR -> monitor().unmonitor(r.nodes());
                default -> throw new IllegalStateException("ViewerRequest.read let " + r.type() + " through");
            }
        }
    }

    private MonitorStream monitor() {
        if (monitor == null) {
            monitor = new MonitorStream(this, viewers.cache());
        }
        return monitor;
    }

    /** The streams and their network runs, from the database; none (and a warning) while it is unavailable. */
    private void listRuns(int id) throws IOException {
        List<LoggedRun> runs;
        try {
            runs = viewers.directory().runs();
        } catch (SQLException e) {
            LOG.warn("viewer {}: cannot list the runs, the database is unavailable: {}", describe(), e.getMessage());
            runs = List.of();
        }
        List<LoggedRun> answer = runs;
        send(w -> {
            w.begin(MessageType.RUN_LIST).putInt(id).putInt(answer.size());
            answer.forEach(r -> r.write(w));
        });
    }

    private void listNodes(int id, String filter) throws IOException {
        List<LoggedNode> nodes = viewers.directory().nodes(filter);
        send(w -> {
            w.begin(MessageType.NODE_LIST).putInt(id).putInt(nodes.size());
            nodes.forEach(n -> n.write(w));
        });
    }

    /**
     * An answer the cache holds whole is found and sent while the writer and the receivers pause for it
     * ({@link org.fdnet.logger.store.QueryPriority}); one that needs the database is not, since the writer must
     * flush first.
     */
    private void history(int id, int[] nodes, long from, long to) throws IOException {
        viewers.queries().begin();
        try {
            List<NetworkEvent> cached = viewers.fromCache(nodes, from, to);
            if (cached != null) {
                sendHistory(id, cached);
                return;
            }
        } finally {
            viewers.queries().end();
        }
        sendHistory(id, events(nodes, from, to));
    }

    private void sendHistory(int id, List<NetworkEvent> events) throws IOException {
        for (int start = 0; start < events.size(); start += Protocol.MAX_EVENTS_PER_FRAME) {
            List<NetworkEvent> chunk = events.subList(start, Math.min(events.size(), start + Protocol.MAX_EVENTS_PER_FRAME));
            sendUnflushed(w -> {
                w.begin(MessageType.HISTORY_CHUNK).putInt(id).putInt(chunk.size());
                chunk.forEach(e -> EventCodec.write(w, e));
            });
        }
        send(w -> w.begin(MessageType.HISTORY_END).putInt(id).putLong(events.size()));
    }

    private List<NetworkEvent> events(int[] nodes, long from, long to) throws IOException {
        List<NetworkEvent> events;
        try {
            events = viewers.history(nodes, from, to);
        } catch (SQLException e) {
            LOG.warn("history for {} failed: {}", describe(), e.getMessage());
            refuse(ErrorCode.INTERNAL, "database unavailable for history: " + e.getMessage());
            throw new IOException("history failed", e);
        }
        return events;
    }

    /** Sends monitored events (from the stream's thread). */
    void sendMonitored(List<CachedEvent> events) throws IOException {
        send(w -> {
            w.begin(MessageType.MONITOR_EVENTS).putInt(events.size());
            events.forEach(e -> EventCodec.write(w, e.event()));
        });
    }

    @Override
    protected void closed() {
        if (monitor != null) {
            monitor.close();
        }
    }
}
