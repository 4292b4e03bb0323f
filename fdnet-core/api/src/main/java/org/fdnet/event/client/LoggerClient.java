package org.fdnet.event.client;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.RunIdentity;
import org.fdnet.event.wire.ErrorFrame;
import org.fdnet.event.wire.EventCodec;
import org.fdnet.event.wire.Frame;
import org.fdnet.event.wire.FrameReader;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.Hello;
import org.fdnet.event.wire.MessageType;
import org.fdnet.event.wire.Protocol;
import org.fdnet.event.wire.ProtocolException;
import org.fdnet.event.wire.RunFrame;
import org.fdnet.tls.TransportSecurity;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The core's event cache and its client to the logger: an {@link EventSink} that never blocks the
 * runtime and never drops while it has room.
 *
 * <pre>
 *   accept() ── seq++ ──▶ pending (memory) ──┐          ┌──▶ inflight (sent, kept until ACK)
 *        └─ memory full or journal in use ─▶ SpillJournal ─┴─ sender thread ─EVENTS─▶ logger
 *                                                     logger ─ACK(seq committed)─▶ drop inflight ≤ seq
 * </pre>
 *
 * Every accepted event gets the next sequence number of this run. Events stay in memory (or in the
 * journal) until the logger acknowledges that their batch is committed to the database; after a
 * reconnect the logger's WELCOME names the last committed sequence number, everything after it is sent
 * again, and the logger drops what it already holds. That makes delivery exactly-once across reconnects
 * and logger restarts. Order is kept: once the journal is in use, new events go behind it until it is
 * drained. Only when even the journal is full is an event lost: counted ({@link #lostEvents()}) and
 * logged at ERROR, never silently.
 */
public final class LoggerClient implements EventSink {
    private static final Logger LOG = LoggerFactory.getLogger(LoggerClient.class);
    private static final long LOSS_REPORT_NANOS = TimeUnit.SECONDS.toNanos(10);
    private static final int CONNECT_TIMEOUT_MILLIS = 5000;

    private final LoggerClientSettings settings;
    private final UUID run;
    private final RunFrame networkRun; // null: a core that does not say which network run it records
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition work = lock.newCondition();
    private final Condition acked = lock.newCondition();
    private final ArrayDeque<NetworkEvent> inflight = new ArrayDeque<>();
    private final ArrayDeque<NetworkEvent> pending = new ArrayDeque<>();
    private final SpillJournal journal;
    private final Thread sender;

    private long ackedSeq;          // every event up to here is committed by the logger
    private long accepted;
    private long lost;
    private long lastLossReport;
    private boolean connected;
    private volatile boolean closing;
    private volatile Socket socket;

    /**
     * A client for a new run of its own, with a random id; it starts connecting at once, in the background.
     *
     * @param settings the logger's address, the memory and journal bounds, the timeouts
     */
    public LoggerClient(LoggerClientSettings settings) {
        this(settings, UUID.randomUUID());
    }

    /**
     * A client for a given run id: a restarted producer that must resume its run passes the same id.
     *
     * @param settings the logger's address, the memory and journal bounds, the timeouts
     * @param run      the run's id, which the logger resumes when it knows it
     */
    public LoggerClient(LoggerClientSettings settings, UUID run) {
        this(settings, run, null);
    }

    /**
     * A client recording {@code host}'s part of the network run {@code networkRun}: the logger files every event
     * of this client under that run, with the host beside it.
     *
     * @param settings   the logger's address, the memory and journal bounds, the timeouts
     * @param networkRun the network run, as its coordinator decided it
     * @param host       the host this client records
     */
    public LoggerClient(LoggerClientSettings settings, RunIdentity networkRun, String host) {
        this(settings, networkRun, host, 0);
    }

    /**
     * As above, for a host whose clock is {@code clockOffsetMicros} ahead of the run's coordinator's.
     *
     * @param settings          the logger's address, the memory and journal bounds, the timeouts
     * @param networkRun        the network run, as its coordinator decided it
     * @param host              the host this client records
     * @param clockOffsetMicros how far this host's clock is ahead of the coordinator's, µs (negative: behind)
     */
    public LoggerClient(LoggerClientSettings settings, RunIdentity networkRun, String host, long clockOffsetMicros) {
        this(settings, UUID.randomUUID(), new RunFrame(networkRun, host, clockOffsetMicros));
    }

    private LoggerClient(LoggerClientSettings settings, UUID run, RunFrame networkRun) {
        this.settings = settings;
        this.run = run;
        this.networkRun = networkRun;
        this.journal = new SpillJournal(settings.journalDirectory(), settings.journalBytes());
        this.sender = new Thread(this::sendLoop, "fdnet-logger-client");
        sender.setDaemon(true);
        sender.start();
    }

    /**
     * The id of the stream of events this client sends (its run in the logger).
     *
     * @return the id given or made at construction
     */
    public UUID run() {
        return run;
    }

    /**
     * The network run this client records a part of, or {@code null} when it does not say.
     *
     * @return the network run, or null
     */
    public RunIdentity networkRun() {
        return networkRun == null ? null : networkRun.run();
    }

    @Override
    public void accept(NetworkEvent event) {
        lock.lock();
        try {
            if (journal.isEmpty() && inflight.size() + pending.size() < settings.memoryEvents()) {
                pending.addLast(event);
            } else if (!journal.append(event)) {
                countLoss();
                return;
            }
            accepted++;
            if (pending.size() == 1 || pending.size() >= Protocol.MAX_EVENTS_PER_FRAME) {
                work.signal();
            }
        } catch (RuntimeException e) {
            // A journal on a failed disk must not take the Relation down with it: count and report.
            LOG.error("cannot keep event of source {}: {}", event.sourceId(), e.getMessage(), e);
            countLoss();
        } finally {
            lock.unlock();
        }
    }

    private void countLoss() {
        lost++;
        long now = System.nanoTime();
        if (lost == 1 || now - lastLossReport > LOSS_REPORT_NANOS) {
            lastLossReport = now;
            LOG.error("EVENTS LOST: the logger at {}:{} is behind and the journal ({} bytes in {}) is full; {} events "
                            + "lost so far in run {}", settings.host(), settings.port(), journal.bytes(),
                    settings.journalDirectory(), lost, run);
        }
    }

    /** Waits until the logger has committed every accepted event, or the flush timeout passes. */
    @Override
    public void flush() {
        if (!flush(settings.flushTimeout().toMillis())) {
            LOG.warn("{} events of run {} not yet committed by the logger at {}:{} after {} ms", unconfirmed(), run,
                    settings.host(), settings.port(), settings.flushTimeout().toMillis());
        }
    }

    /**
     * True when every accepted event is committed by the logger within the timeout.
     *
     * @param timeoutMillis how long to wait at most, ms
     * @return true when everything accepted is committed; false on timeout or interruption
     */
    public boolean flush(long timeoutMillis) {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMillis);
        lock.lock();
        try {
            work.signal();
            while (ackedSeq < accepted) {
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    return false;
                }
                acked.awaitNanos(left);
            }
            return true;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        } finally {
            lock.unlock();
        }
    }

    /**
     * The client's counts now.
     *
     * @return a consistent snapshot
     */
    public ClientStatus status() {
        lock.lock();
        try {
            return new ClientStatus(connected, accepted, ackedSeq, inflight.size() + pending.size(), journal.count(),
                    journal.bytes(), lost);
        } finally {
            lock.unlock();
        }
    }

    /**
     * Events lost because even the journal was full.
     *
     * @return the count since the client started
     */
    public long lostEvents() {
        return status().lost();
    }

    private long unconfirmed() {
        lock.lock();
        try {
            return accepted - ackedSeq;
        } finally {
            lock.unlock();
        }
    }

    @Override
    public void close() {
        flush();
        closing = true;
        closeSocket();
        sender.interrupt();
        try {
            sender.join(5000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        ClientStatus s = status();
        lock.lock();
        try {
            journal.close();
        } finally {
            lock.unlock();
        }
        if (s.lost() > 0 || s.accepted() > s.acked()) {
            LOG.error("logger client for run {} closed with {} events lost and {} not confirmed by the logger",
                    run, s.lost(), s.accepted() - s.acked());
        }
    }

    private void sendLoop() {
        boolean reported = false;
        while (!closing) {
            try (Socket s = TransportSecurity.connect(settings.host(), settings.port(), CONNECT_TIMEOUT_MILLIS)) {
                // Every read — the handshake's and the ACKs' — gives up after the silence timeout: the logger repeats
                // its last ACK every second, so a silent connection is a dead one (a partition drops, never resets).
                s.setSoTimeout((int) settings.silenceTimeout().toMillis());
                socket = s;
                serve(s);
                reported = false;
            } catch (IOException e) {
                if (closing) {
                    break;
                }
                if (!reported) {
                    LOG.warn("logger at {}:{} unreachable ({}); keeping events and retrying every {} ms",
                            settings.host(), settings.port(), e.getMessage(), settings.reconnectDelay().toMillis());
                    reported = true;
                }
            } catch (InterruptedException e) {
                break;
            } finally {
                setConnected(false);
            }
            try {
                Thread.sleep(settings.reconnectDelay().toMillis());
            } catch (InterruptedException e) {
                break;
            }
        }
    }

    private void serve(Socket s) throws IOException, InterruptedException {
        OutputStream out = new BufferedOutputStream(s.getOutputStream(), 1 << 16);
        FrameReader in = new FrameReader(new BufferedInputStream(s.getInputStream()), Protocol.DEFAULT_MAX_FRAME_BYTES);
        FrameWriter w = new FrameWriter();
        Hello.core(run, settings.coreName()).write(w);
        w.writeTo(out);
        out.flush();
        Frame welcome = in.read();
        if (welcome == null) {
            throw new ProtocolException("logger closed the connection during the handshake");
        }
        if (welcome.type() == MessageType.ERROR) {
            throw new ProtocolException("logger refused: " + ErrorFrame.read(welcome).message());
        }
        if (welcome.type() != MessageType.WELCOME) {
            throw new ProtocolException("expected WELCOME, got " + welcome.type());
        }
        int version = welcome.getShort();
        if (version != Protocol.VERSION) {
            throw new ProtocolException("the logger speaks protocol version " + version + ", this core version " + Protocol.VERSION);
        }
        long committed = welcome.getLong();
        if (networkRun != null) {
            networkRun.write(w);
            w.writeTo(out);
            out.flush();
        }
        resumeAfter(committed);
        Thread ackReader = new Thread(() -> readAcks(in), "fdnet-logger-client-acks");
        ackReader.setDaemon(true);
        ackReader.start();
        try {
            sendEvents(w, out);
        } finally {
            closeSocket();
            ackReader.join(2000);
        }
    }

    /** After a (re)connect: drop what the logger committed, send the rest again, oldest first. */
    private void resumeAfter(long committed) {
        lock.lock();
        try {
            if (committed < ackedSeq) {
                LOG.error("logger reports run {} committed up to {} but had acknowledged {}: was its database reset?",
                        run, committed, ackedSeq);
            }
            dropAcked(committed);
            while (!inflight.isEmpty()) {
                pending.addFirst(inflight.pollLast());
            }
            connected = true;
            LOG.info("connected to logger at {}:{} for run {}; resuming after event {}", settings.host(), settings.port(),
                    run, ackedSeq);
        } finally {
            lock.unlock();
        }
    }

    private void sendEvents(FrameWriter w, OutputStream out) throws IOException, InterruptedException {
        List<NetworkEvent> batch = new ArrayList<>(Protocol.MAX_EVENTS_PER_FRAME);
        while (!closing) {
            long firstSeq;
            lock.lock();
            try {
                while (connected && pending.isEmpty() && (journal.isEmpty() || inflight.size() >= settings.memoryEvents())) {
                    work.await(200, TimeUnit.MILLISECONDS);
                    if (closing) {
                        return;
                    }
                }
                if (!connected) {
                    return;
                }
                firstSeq = ackedSeq + inflight.size() + 1;
                batch.clear();
                while (batch.size() < Protocol.MAX_EVENTS_PER_FRAME && !pending.isEmpty()) {
                    batch.add(pending.pollFirst());
                }
                if (batch.isEmpty()) {
                    batch.addAll(journal.take(Protocol.MAX_EVENTS_PER_FRAME));
                }
                inflight.addAll(batch);
            } finally {
                lock.unlock();
            }
            w.begin(MessageType.EVENTS).putLong(firstSeq).putInt(batch.size());
            for (NetworkEvent e : batch) {
                EventCodec.write(w, e);
            }
            w.writeTo(out);
            if (!hasPending()) {
                out.flush();
            }
        }
    }

    private boolean hasPending() {
        lock.lock();
        try {
            return !pending.isEmpty();
        } finally {
            lock.unlock();
        }
    }

    private void readAcks(FrameReader in) {
        try {
            Frame f;
            while ((f = in.read()) != null) {
                if (f.type() == MessageType.ACK) {
                    long seq = f.getLong();
                    lock.lock();
                    try {
                        dropAcked(seq);
                        acked.signalAll();
                        work.signal();
                    } finally {
                        lock.unlock();
                    }
                } else if (f.type() == MessageType.ERROR) {
                    LOG.warn("logger closed the connection of run {}: {}", run, ErrorFrame.read(f).message());
                    break;
                } else {
                    throw new ProtocolException("unexpected " + f.type() + " from the logger");
                }
            }
        } catch (java.net.SocketTimeoutException e) {
            if (!closing) {
                LOG.warn("logger at {}:{} silent for {} ms (partitioned?); connecting again", settings.host(),
                        settings.port(), settings.silenceTimeout().toMillis());
            }
        } catch (IOException e) {
            if (!closing) {
                LOG.warn("connection to logger at {}:{} lost: {}", settings.host(), settings.port(), e.getMessage());
            }
        } finally {
            setConnected(false);
            closeSocket();
        }
    }

    private void dropAcked(long seq) {
        while (ackedSeq < seq && !inflight.isEmpty()) {
            inflight.pollFirst();
            ackedSeq++;
        }
    }

    private void setConnected(boolean value) {
        lock.lock();
        try {
            connected = value;
            work.signalAll();
        } finally {
            lock.unlock();
        }
    }

    private void closeSocket() {
        Socket s = socket;
        if (s != null) {
            try {
                s.close();
            } catch (IOException e) {
                LOG.debug("closing logger socket: {}", e.getMessage());
            }
        }
    }
}
