package org.fdnet.corba;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicInteger;
import org.fdnet.corba.idl.UnknownLink;
import org.fdnet.corba.idl.Value;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.corba.idl.ValueSink;
import org.omg.CORBA.SystemException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The sending end of one cross-host link: values of one local node go, in order and without loss, to a
 * {@link ValueSink} on another host.
 *
 * <pre>
 *   offer(v) ──▶ ring [headSeq … sendSeq … tailSeq)      (bounded: LinkSettings.capacity)
 *                 │ `window` caller threads: each takes up to batchMax values and calls the peer
 *                 ▼
 *               deliver(ValueBatch) ──▶ peer ──▶ returns next expected seq ──▶ headSeq moves
 * </pre>
 *
 * Values leave the ring only when the peer has applied them (the reply of {@code deliver}). When a call
 * fails the link is <em>broken</em>: it rewinds to the oldest unacknowledged value and, every
 * {@code retryMillis}, probes the peer with one batch; {@link #retarget} points it at a restarted peer.
 * After a (re)start only one batch is in flight until the peer has acknowledged one, so a fresh receiver
 * learns where the sequence stands before batches can overtake each other.
 */
public final class OutboundLink implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(OutboundLink.class);
    private static final AtomicInteger THREADS = new AtomicInteger();
    /** The longest a writer waits for room while the peer acknowledges nothing. */
    static final long MAX_WRITER_WAIT_MILLIS = 2_000;

    /** Told when a link breaks and when it carries values again. */
    public interface StateListener {
        void broken(OutboundLink link, String reason);

        void restored(OutboundLink link);
    }

    private final long id;
    private final String description;
    private final LinkSettings settings;
    private final StateListener listener;
    private final Thread[] callers;

    private final Object lock = new Object();
    private final Object[] ring;
    private final String[] originStreams;
    private final long[] originSeqs;
    private final String stream;
    private final int mask;
    private long headSeq;
    private long sendSeq;
    private long tailSeq;
    private int inFlight;
    private boolean probing = true;
    private boolean broken;
    private boolean closed;
    private boolean writerWaiting;
    private int waitingCallers;
    private long lost;
    private long nextProbeNanos;
    private long lastProgressNanos;
    private long fullSinceNanos;
    private boolean stallReported;
    private long generation;
    private ValueSink sink;

    /**
     * @param stream the identity values written locally get here (see {@link ValueOrigin}): unique per host
     *               incarnation and link, and kept when the link is re-pointed at a restarted peer
     */
    public OutboundLink(long id, String stream, String description, ValueSink sink, LinkSettings settings,
                        StateListener listener) {
        this.id = id;
        this.stream = Objects.requireNonNull(stream, "stream");
        this.description = Objects.requireNonNull(description, "description");
        this.sink = Objects.requireNonNull(sink, "sink");
        this.settings = Objects.requireNonNull(settings, "settings");
        this.listener = Objects.requireNonNull(listener, "listener");
        this.ring = new Object[settings.capacity()];
        this.originStreams = new String[settings.capacity()];
        this.originSeqs = new long[settings.capacity()];
        this.mask = settings.capacity() - 1;
        this.callers = new Thread[settings.window()];
        for (int i = 0; i < callers.length; i++) {
            callers[i] = new Thread(this::sendLoop, "fdnet-link-" + id + "-" + THREADS.incrementAndGet());
            callers[i].setDaemon(true);
            callers[i].start();
        }
    }

    public long id() {
        return id;
    }

    public String description() {
        return description;
    }

    /**
     * Queues one value. While the ring is full and the peer reachable the writer waits (flow control, no
     * loss) — but never longer than {@link #MAX_WRITER_WAIT_MILLIS} without the peer acknowledging anything:
     * a writer blocked for good would stall its whole engine, and two hosts flooding each other could
     * deadlock. Then, as while the peer is down, the oldest value is dropped and counted.
     */
    public void offer(Object value) {
        offer(value, null);
    }

    /** Queues one value that entered the links at {@code origin} ({@code null}: written on this host). */
    public void offer(Object value, ValueOrigin origin) {
        boolean reportStall = false;
        synchronized (lock) {
            while (!closed && tailSeq - headSeq == ring.length) {
                long now = System.nanoTime();
                if (fullSinceNanos == 0) {
                    fullSinceNanos = now; // the stall clock starts when the ring fills, not at the last ack
                }
                boolean stalled = now - Math.max(lastProgressNanos, fullSinceNanos) > MAX_WRITER_WAIT_MILLIS * 1_000_000L;
                if (broken || stalled) {
                    ring[(int) (headSeq & mask)] = null;
                    originStreams[(int) (headSeq & mask)] = null;
                    headSeq++;
                    sendSeq = Math.max(sendSeq, headSeq);
                    lost++;
                    reportStall = stalled && !broken && !stallReported;
                    stallReported |= reportStall;
                    break;
                }
                writerWaiting = true;
                try {
                    lock.wait(settings.retryMillis());
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
            }
            if (closed) {
                return;
            }
            int slot = (int) (tailSeq & mask);
            ring[slot] = value;
            originStreams[slot] = origin == null ? stream : origin.stream();
            originSeqs[slot] = origin == null ? tailSeq : origin.seq();
            tailSeq++;
            if (waitingCallers > 0) {
                if (writerWaiting) {
                    lock.notifyAll();
                } else {
                    lock.notify();
                }
            }
        }
        if (reportStall) {
            LOG.warn("link {}: the peer acknowledged nothing for {} ms with {} values waiting; dropping the oldest"
                    + " until it catches up", description, MAX_WRITER_WAIT_MILLIS, ring.length);
        }
    }

    /** Points the link at a new sink (its peer restarted); everything unacknowledged is sent again. */
    public void retarget(ValueSink newSink) {
        synchronized (lock) {
            sink = Objects.requireNonNull(newSink, "newSink");
            generation++;
            inFlight = 0; // calls to the old sink no longer count against the window
            sendSeq = headSeq;
            probing = true;
            broken = false;
            lock.notifyAll();
        }
    }

    public boolean broken() {
        synchronized (lock) {
            return broken;
        }
    }

    /** Values dropped because the ring overflowed while the peer was down. */
    public long lost() {
        synchronized (lock) {
            return lost;
        }
    }

    /** Values offered and not yet acknowledged by the peer. */
    public long pending() {
        synchronized (lock) {
            return tailSeq - headSeq;
        }
    }

    /** Values the peer has acknowledged. */
    public long acknowledged() {
        synchronized (lock) {
            return headSeq - lost;
        }
    }

    /** One of {@code window} caller threads: takes the next batch, calls the peer, acknowledges. */
    private void sendLoop() {
        while (true) {
            Object[] values;
            long firstSeq;
            long callGeneration;
            ValueSink target;
            String originStream;
            long originFirstSeq;
            synchronized (lock) {
                while (!closed && !readyToSend()) {
                    waitingCallers++;
                    try {
                        lock.wait(broken ? settings.retryMillis() : 0);
                    } catch (InterruptedException e) {
                        return;
                    } finally {
                        waitingCallers--;
                    }
                }
                if (closed) {
                    return;
                }
                int max = (int) Math.min(tailSeq - sendSeq, settings.batchMax());
                int first = (int) (sendSeq & mask);
                originStream = originStreams[first];
                originFirstSeq = originSeqs[first];
                // One batch, one origin stream with consecutive numbers: cut where that changes.
                int n = 1;
                while (n < max) {
                    int slot = (int) ((sendSeq + n) & mask);
                    if (!originStreams[slot].equals(originStream) || originSeqs[slot] != originFirstSeq + n) {
                        break;
                    }
                    n++;
                }
                values = new Object[n];
                for (int i = 0; i < n; i++) {
                    values[i] = ring[(int) ((sendSeq + i) & mask)];
                }
                firstSeq = sendSeq;
                sendSeq += n;
                inFlight++;
                callGeneration = generation;
                target = sink;
            }
            call(target, firstSeq, originStream, originFirstSeq, values, callGeneration);
        }
    }

    private boolean readyToSend() {
        if (sendSeq == tailSeq) {
            return false;
        }
        if (broken) {
            return inFlight == 0 && System.nanoTime() >= nextProbeNanos; // probe the peer again
        }
        return inFlight < (probing ? 1 : settings.window());
    }

    private void call(ValueSink target, long firstSeq, String originStream, long originFirstSeq, Object[] values,
                      long callGeneration) {
        Value[] encoded = new Value[values.length];
        for (int i = 0; i < values.length; i++) {
            encoded[i] = ValueCodec.encode(values[i]);
        }
        long expected;
        String failure;
        try {
            expected = target.deliver(new ValueBatch(id, firstSeq, originStream, originFirstSeq, encoded));
            failure = null;
        } catch (UnknownLink e) {
            expected = -1;
            failure = "the peer does not know link " + id + " (it restarted and is not re-wired yet)";
        } catch (SystemException e) {
            expected = -1;
            failure = e.getClass().getSimpleName() + " " + e.getMessage();
        }
        boolean restored = false;
        boolean newlyBroken = false;
        synchronized (lock) {
            if (callGeneration == generation) {
                inFlight--;
                if (failure == null) {
                    acknowledge(expected);
                    restored = broken;
                    broken = false;
                    probing = false;
                } else {
                    newlyBroken = !broken;
                    broken = true;
                    sendSeq = headSeq;
                    probing = true;
                    nextProbeNanos = System.nanoTime() + settings.retryMillis() * 1_000_000L;
                }
            }
            lock.notifyAll();
        }
        if (newlyBroken) {
            LOG.warn("link {} broken: {}", description, failure);
            listener.broken(this, failure);
        } else if (restored) {
            LOG.info("link {} carries values again", description);
            listener.restored(this);
        }
    }

    private void acknowledge(long expected) {
        long upTo = Math.min(expected, tailSeq);
        if (upTo > headSeq) {
            lastProgressNanos = System.nanoTime();
            fullSinceNanos = 0;
            stallReported = false;
        }
        while (headSeq < upTo) {
            ring[(int) (headSeq & mask)] = null;
            originStreams[(int) (headSeq & mask)] = null;
            headSeq++;
        }
        if (sendSeq < headSeq) {
            sendSeq = headSeq;
        }
        if (writerWaiting) {
            writerWaiting = false;
        }
    }

    @Override
    public void close() {
        synchronized (lock) {
            closed = true;
            lock.notifyAll();
        }
        for (Thread t : callers) {
            t.interrupt();
        }
    }
}
