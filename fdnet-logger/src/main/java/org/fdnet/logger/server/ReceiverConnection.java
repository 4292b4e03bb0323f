package org.fdnet.logger.server;

import java.io.IOException;
import java.net.Socket;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.wire.ErrorCode;
import org.fdnet.event.wire.EventCodec;
import org.fdnet.event.wire.EventsFrame;
import org.fdnet.event.wire.Frame;
import org.fdnet.event.wire.FrameReader;
import org.fdnet.event.wire.Hello;
import org.fdnet.event.wire.MessageType;
import org.fdnet.event.wire.RunFrame;
import org.fdnet.event.wire.Protocol;
import org.fdnet.event.wire.ProtocolException;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.cache.RunProgress;
import org.fdnet.logger.store.QueryPriority;
import org.fdnet.logger.store.SourceDirectory;
import org.fdnet.tls.PeerCertificate;
import org.fdnet.tls.Right;
import org.fdnet.tls.TransportSecurity;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A core's connection to the receiver server. After the handshake (which names the run and tells the core
 * the last committed sequence number), it reads EVENTS frames: a frame is checked whole before any of its
 * events is taken, then each event is built once with its global source id (the core's node ids, looked up
 * once per node), and events the run already delivered are skipped (a reconnecting core sends again what was
 * not acknowledged). Before each frame it waits
 * while the cache is at its critical level: the socket is not read, and TCP pushes back on the core.
 * The writer's commits come back as ACK frames. Over TLS, a core whose certificate may not {@code record} (the network's
 * permissions) is refused at the handshake with the reason, and nothing it sends is read.
 */
final class ReceiverConnection extends Connection {
    private static final Logger LOG = LoggerFactory.getLogger(ReceiverConnection.class);

    private final EventCache cache;
    private final SourceDirectory directory;
    private final RunOwners owners;
    private final QueryPriority queries;
    /** Node ids of a core up to here are looked up in {@link #knownGlobalIds}: 1 MiB of table at most. */
    private static final int MAX_TABLED_LOCAL_ID = 1 << 18;

    private RunProgress run;
    /** Global id + 1 by the core's node id, 0 where not looked up yet: the directory is asked once per node. */
    private int[] knownGlobalIds = new int[64];
    private final EventCodec.SourceIdMap globalIds = this::globalId;
    private final Object ackLock = new Object();
    private long ackWanted;

    ReceiverConnection(Socket socket, int maxFrameBytes, EventCache cache, SourceDirectory directory, RunOwners owners,
                       QueryPriority queries) {
        super(socket, maxFrameBytes);
        this.cache = cache;
        this.directory = directory;
        this.owners = owners;
        this.queries = queries;
    }

    @Override
    protected boolean handshake(Hello hello) throws IOException {
        if (hello.role() != Protocol.ROLE_CORE) {
            throw new ProtocolException("the receiver server serves cores; use the sender port for viewers");
        }
        String peer = PeerCertificate.name(socket);
        String refusal = peer == null ? null : TransportSecurity.permissions().refusal(peer, Right.RECORD, "");
        if (refusal != null) {
            LOG.warn("refusing core {}: {}", describe(), refusal);
            refuse(ErrorCode.BAD_REQUEST, "this logger does not record your events: " + refusal);
            return false;
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
        while (true) {
            if (cache.pressured()) {
                state(ConnectionState.WAITING);
                cache.awaitRoom();
                state(ConnectionState.ACTIVATED);
            }
            queries.yieldToQueries(); // a viewer's query first: the core's TCP buffers meanwhile, nothing is lost
            Frame f = in.read();
            if (f == null) {
                return;
            }
            frames++;
            if (f.type() == MessageType.RUN) {
                joinNetworkRun(RunFrame.read(f));
                continue;
            }
            EventsFrame events = EventsFrame.check(f); // the whole frame is checked before any of it is taken
            take(f, events.firstSeq(), events.count());
        }
    }

    /** Files this connection's run under the network run the core names (idempotent: a reconnect says it again). */
    private void joinNetworkRun(RunFrame part) throws IOException {
        try {
            directory.joinNetworkRun(run, part);
        } catch (SQLException e) {
            throw new IOException("cannot record that run " + run.uuid() + " is host " + part.host() + " of network run "
                    + part.run().id() + ": " + e.getMessage(), e);
        }
        LOG.info("core {}: run {} is host {} of {} run {}", describe(), run.uuid(), part.host(), part.run().network(),
                part.run().id());
    }

    /**
     * Takes the events of a checked frame (its cursor on the first event): each is built once, with its global
     * source id; those the run already delivered are stepped over.
     */
    private void take(Frame f, long firstSeq, int count) throws IOException, InterruptedException {
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
            List<CachedEvent> fresh = new ArrayList<>(count);
            for (int i = 0; i < count; i++) {
                long seq = firstSeq + i;
                if (seq <= received) {
                    EventCodec.skip(f);
                    continue;
                }
                NetworkEvent e = EventCodec.read(f, globalIds);
                if (e instanceof NodeNamedEvent named) {
                    directory.named(run, named);
                }
                fresh.add(new CachedEvent(e, run, seq, cache.sizeOf(e), now));
            }
            if (!fresh.isEmpty()) {
                cache.add(fresh);
                run.received(firstSeq + count - 1);
            }
        }
    }

    /**
     * The global id of a core's node id: from this connection's table once known (a run's mapping never
     * changes), else from the directory — when a new block of ids cannot be had (database down) this core waits.
     */
    private int globalId(int localId) throws InterruptedException {
        if (localId >= 0 && localId < knownGlobalIds.length && knownGlobalIds[localId] != 0) {
            return knownGlobalIds[localId] - 1;
        }
        while (true) {
            try {
                int id = directory.globalId(run, localId);
                remember(localId, id);
                return id;
            } catch (SQLException e) {
                LOG.warn("{}: cannot reserve source ids ({}); waiting for the database", describe(), e.getMessage());
                state(ConnectionState.WAITING);
                Thread.sleep(1000);
            }
        }
    }

    /** Keeps small non-negative node ids (a core numbers its nodes from 0) in a table; others ask the directory. */
    private void remember(int localId, int globalId) {
        if (localId < 0 || localId >= MAX_TABLED_LOCAL_ID || globalId == Integer.MAX_VALUE) {
            return;
        }
        if (localId >= knownGlobalIds.length) {
            knownGlobalIds = Arrays.copyOf(knownGlobalIds, Math.min(MAX_TABLED_LOCAL_ID,
                    Math.max(localId + 1, knownGlobalIds.length * 2)));
        }
        knownGlobalIds[localId] = globalId + 1; // 0: not known yet
    }

    @Override
    protected void closed() {
        if (run != null) {
            owners.release(run, this);
        }
    }
}
