package org.fdnet.logger.server;

import java.io.IOException;
import java.net.Socket;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.wire.ErrorCode;
import org.fdnet.event.wire.EventCodec;
import org.fdnet.event.wire.Frame;
import org.fdnet.event.wire.FrameReader;
import org.fdnet.event.wire.Hello;
import org.fdnet.event.wire.MessageType;
import org.fdnet.event.wire.Protocol;
import org.fdnet.event.wire.ProtocolException;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.cache.RunProgress;
import org.fdnet.logger.store.SourceDirectory;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A core's connection to the receiver server. After the handshake (which names the run and tells the core
 * the last committed sequence number), it reads EVENTS frames: a frame is decoded and checked whole before
 * any of its events is taken, events the run already delivered are skipped (a reconnecting core sends again
 * what was not acknowledged), and the core's node ids become global source ids. Before each frame it waits
 * while the cache is at its critical level: the socket is not read, and TCP pushes back on the core.
 * The writer's commits come back as ACK frames.
 */
final class ReceiverConnection extends Connection {
    private static final Logger LOG = LoggerFactory.getLogger(ReceiverConnection.class);

    private final EventCache cache;
    private final SourceDirectory directory;
    private final RunOwners owners;
    private RunProgress run;
    private final Object ackLock = new Object();
    private long ackWanted;

    ReceiverConnection(Socket socket, int maxFrameBytes, EventCache cache, SourceDirectory directory, RunOwners owners) {
        super(socket, maxFrameBytes);
        this.cache = cache;
        this.directory = directory;
        this.owners = owners;
    }

    @Override
    protected boolean handshake(Hello hello) throws IOException {
        if (hello.role() != Protocol.ROLE_CORE) {
            throw new ProtocolException("the receiver server serves cores; use the sender port for viewers");
        }
        try {
            run = directory.openRun(hello.run(), hello.name());
        } catch (SQLException e) {
            LOG.warn("refusing core {}: database unavailable to open run {}: {}", describe(), hello.run(), e.getMessage());
            refuse(ErrorCode.INTERNAL, "database unavailable, retry later: " + e.getMessage());
            return false;
        }
        owners.claim(run, this);
        Thread acker = new Thread(this::sendAcks, "fdnet-acks-" + socket.getRemoteSocketAddress());
        acker.setDaemon(true);
        acker.start();
        synchronized (run) {
            run.ackListener(this::ack);
            long committed = run.committed();
            send(w -> w.begin(MessageType.WELCOME).putShort(Protocol.VERSION).putLong(committed));
        }
        LOG.info("core {} connected: run {} (id {}), resuming after event {}", describe(), run.uuid(), run.runId(),
                run.committed());
        return true;
    }

    /**
     * Called by the writer after a commit: only records the number and wakes this connection's acker, so a
     * core that does not read its socket can stall nothing but itself.
     */
    private void ack(long seq) {
        synchronized (ackLock) {
            if (seq > ackWanted) {
                ackWanted = seq;
                ackLock.notifyAll();
            }
        }
    }

    private void sendAcks() {
        long sent = 0;
        try {
            while (!socket.isClosed()) {
                long seq;
                synchronized (ackLock) {
                    while (ackWanted <= sent && !socket.isClosed()) {
                        ackLock.wait(500);
                    }
                    seq = ackWanted;
                }
                if (seq > sent) {
                    send(w -> w.begin(MessageType.ACK).putLong(seq));
                    sent = seq;
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException e) {
            LOG.debug("cannot acknowledge to {}: {}", describe(), e.getMessage());
        }
    }

    @Override
    protected void serve(FrameReader in) throws IOException, InterruptedException {
        List<NetworkEvent> decoded = new ArrayList<>(Protocol.MAX_EVENTS_PER_FRAME);
        while (true) {
            if (cache.pressured()) {
                state(ConnectionState.WAITING);
                cache.awaitRoom();
                state(ConnectionState.ACTIVATED);
            }
            Frame f = in.read();
            if (f == null) {
                return;
            }
            frames++;
            if (f.type() != MessageType.EVENTS) {
                throw new ProtocolException("a core may only send EVENTS after the handshake, got " + f.type());
            }
            long firstSeq = f.getLong();
            int count = f.getCount(EventCodec.MIN_EVENT_BYTES);
            decoded.clear();
            for (int i = 0; i < count; i++) {
                decoded.add(EventCodec.read(f));
            }
            f.expectEnd();
            if (firstSeq < 1) {
                throw new ProtocolException("EVENTS with sequence number " + firstSeq + " (they start at 1)");
            }
            take(firstSeq, decoded);
        }
    }

    private void take(long firstSeq, List<NetworkEvent> decoded) throws IOException, InterruptedException {
        synchronized (run) {
            if (!owners.owns(run, this)) {
                throw new IOException("run taken over by a newer connection");
            }
            long received = run.received();
            if (firstSeq > received + 1) {
                throw new ProtocolException("sequence gap in run " + run.uuid() + ": expected at most " + (received + 1)
                        + ", got " + firstSeq);
            }
            long now = System.nanoTime();
            List<CachedEvent> fresh = new ArrayList<>(decoded.size());
            for (int i = 0; i < decoded.size(); i++) {
                long seq = firstSeq + i;
                if (seq <= received) {
                    continue;
                }
                NetworkEvent e = EventCodec.withSource(decoded.get(i), globalId(decoded.get(i).sourceId()));
                if (e instanceof NodeNamedEvent named) {
                    directory.named(run, named);
                }
                fresh.add(new CachedEvent(e, run, seq, cache.sizeOf(e), now));
            }
            if (!fresh.isEmpty()) {
                cache.add(fresh);
                run.received(firstSeq + decoded.size() - 1);
            }
        }
    }

    /** The global id; when a new block of ids cannot be had (database down) this core waits. */
    private int globalId(int localId) throws InterruptedException {
        while (true) {
            try {
                return directory.globalId(run, localId);
            } catch (SQLException e) {
                LOG.warn("{}: cannot reserve source ids ({}); waiting for the database", describe(), e.getMessage());
                state(ConnectionState.WAITING);
                Thread.sleep(1000);
            }
        }
    }

    @Override
    protected void closed() {
        if (run != null) {
            owners.release(run, this);
        }
    }
}
