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
 *
 * <p>{@code offer} runs on the writer's thread under the engine's commit lock, so it never waits for a reply:
 * a blocking remote call there would stall the whole engine. When the link is idle — nothing in flight, the peer
 * has acknowledged before, the value the only one waiting — the writer puts that value's call on the wire itself
 * ({@link DirectDelivery}: a two-way call whose reply comes back on the ORB's reader thread), so a lone value does
 * not pay for waking a sender thread; a reply that does not come within the ORB's reply timeout fails the call
 * like a sender thread's ({@link DirectCallWatch} looks for overdue calls). Everything else goes through the {@code window} sender threads, and one caller of an
 * idle link may watch for the next value for {@link LinkSettings#spinMicros()} before it parks.
 */
public final class OutboundLink implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(OutboundLink.class);
    private static final AtomicInteger THREADS = new AtomicInteger();
    /** The longest a writer waits for room while the peer acknowledges nothing. */
    public static final long MAX_WRITER_WAIT_MILLIS = 2_000;
    /**
     * A lone value goes from the writer's thread only this soon after the peer last answered: the ORB closes a
     * connection that received nothing for its call timeout ({@link OrbSettings}), and a call on a closed one
     * would open a new connection — a connect that may take the connect timeout — on the writer's thread.
     */
    static final long DIRECT_AFTER_REPLY_MILLIS = 1_000;

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
    /** One idle caller is watching {@link #offered} instead of waiting on the lock: offer() need not notify. */
    private boolean watching;
    /** {@link #tailSeq} as the watching caller reads it without the lock. */
    private volatile long offered;
    private long lost;
    private long nextProbeNanos;
    private long lastProgressNanos;
    private long fullSinceNanos;
    private boolean stallReported;
    private long generation;
    private ValueSink sink;
    /** The longest {@code deliver} call since {@link #takeLongestCallMillis} was last asked, ms. */
    private long longestCallMillis;
    /** Sends an idle link's lone value from the writer's thread; {@code null} for a peer in this ORB. */
    private DirectDelivery direct;
    /** The call {@link #direct} has on the wire, settled by its reply or by its deadline. */
    private Batch directPending;
    private long directDeadlineNanos;
    private long directCalls;
    private long lastReplyNanos;

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
        this.direct = DirectDelivery.open(id, sink, directReplies());
        if (direct != null) {
            DirectCallWatch.watch(this);
        }
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
        Batch directBatch = null;
        DirectDelivery via = null;
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
            offered = tailSeq;
            if (mayDeliverDirectly()) {
                directBatch = takeBatch(true);
                via = direct;
            } else if (waitingCallers > 0 && !watching) {
                if (writerWaiting) {
                    lock.notifyAll();
                } else {
                    lock.notify();
                }
            }
        }
        if (directBatch != null) {
            sendDirectly(via, directBatch);
        }
        if (reportStall) {
            LOG.warn("link {}: the peer acknowledged nothing for {} ms with {} values waiting; dropping the oldest"
                    + " until it catches up", description, MAX_WRITER_WAIT_MILLIS, ring.length);
        }
    }

    /** Points the link at a new sink (its peer restarted); everything unacknowledged is sent again. */
    public void retarget(ValueSink newSink) {
        DirectDelivery old;
        synchronized (lock) {
            sink = Objects.requireNonNull(newSink, "newSink");
            old = direct;
            direct = DirectDelivery.open(id, newSink, directReplies());
            if (direct != null) {
                DirectCallWatch.watch(this);
            }
            directPending = null; // its reply, if any, belongs to the old generation
            generation++;
            inFlight = 0; // calls to the old sink no longer count against the window
            sendSeq = headSeq;
            probing = true;
            broken = false;
            lock.notifyAll();
        }
        if (old != null) {
            old.close();
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

    /**
     * The longest a sender thread's {@code deliver} call took — answered, refused or timed out — since this was last asked
     * (then 0 again): what a silent peer costs the link's caller threads, bounded by the ORB's call timeout.
     */
    public long takeLongestCallMillis() {
        synchronized (lock) {
            long longest = longestCallMillis;
            longestCallMillis = 0;
            return longest;
        }
    }

    /** Calls the writers' threads put on the wire themselves (an idle link's lone values). */
    public long directCalls() {
        synchronized (lock) {
            return directCalls;
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
        Batch batch;
        while ((batch = nextBatch()) != null) {
            call(batch);
        }
    }

    /**
     * Fails the direct call whose reply is overdue, if there is one. Its reply handler is retired with it and a
     * new one takes its place, so a reply that comes after all (a partition healing) finds no handler instead of
     * settling a later call.
     */
    void settleOverdueDirectCall() {
        Batch overdue;
        DirectDelivery retired;
        int timeout;
        synchronized (lock) {
            if (directPending == null || closed || System.nanoTime() - directDeadlineNanos < 0) {
                return;
            }
            overdue = directPending;
            retired = direct;
            timeout = retired.replyTimeoutMillis();
            direct = DirectDelivery.open(id, sink, directReplies());
        }
        retired.close();
        settle(overdue, -1, "no reply within " + timeout + " ms");
    }

    /** Under the lock: the link is idle, so the value just offered may go from the writer's thread. */
    private boolean mayDeliverDirectly() {
        return direct != null && directPending == null && inFlight == 0 && !probing && !broken
                && sendSeq == tailSeq - 1 && !LinkFaults.armed()
                && System.nanoTime() - lastReplyNanos < DIRECT_AFTER_REPLY_MILLIS * 1_000_000L;
    }

    /** Outside the lock, on the writer's thread: puts the call on the wire; its reply settles it. */
    private void sendDirectly(DirectDelivery via, Batch batch) {
        try {
            via.send(batch.target(), delivery(batch));
        } catch (SystemException e) {
            settle(batch, -1, DirectDelivery.failure(e, id));
        }
    }

    private DirectDelivery.Replies directReplies() {
        return new DirectDelivery.Replies() {
            @Override
            public void replied(long expected) {
                Batch batch = pendingDirect();
                if (batch != null) {
                    settle(batch, expected, null);
                }
            }

            @Override
            public void failed(String reason) {
                Batch batch = pendingDirect();
                if (batch != null) {
                    settle(batch, -1, reason);
                }
            }
        };
    }

    private Batch pendingDirect() {
        synchronized (lock) {
            return directPending;
        }
    }

    /**
     * Waits until a batch may go and takes it; {@code null} when the link closed. While the link is idle one
     * caller <em>watches</em> for the next value instead of parking (see {@link #watchForOffer}): the values
     * are offered under the engine's commit lock, so the writer cannot send them itself, and waking a parked
     * thread would add its wake-up to every lone value's latency.
     */
    private Batch nextBatch() {
        boolean watched = false;
        // One watch per idle spell: a watch that ran out without a value ends in a park, or an idle link
        // would keep one thread spinning (yielding, but burning a core) for as long as it stays idle.
        boolean mayWatch = true;
        while (true) {
            long watchFrom;
            synchronized (lock) {
                if (watched) {
                    watching = false; // from here on offer() notifies again; readyToSend() is re-checked below
                    watched = false;
                }
                if (closed) {
                    return null;
                }
                if (readyToSend()) {
                    Batch batch = takeBatch(false);
                    if (waitingCallers > 0 && readyToSend()) {
                        lock.notify(); // values offered during a watch were not announced: share them out
                    }
                    return batch;
                }
                if (watching || !mayWatch || !idleWithRoom() || settings.spinMicros() == 0) {
                    waitingCallers++;
                    try {
                        lock.wait(broken ? settings.retryMillis() : 0);
                    } catch (InterruptedException e) {
                        return null;
                    } finally {
                        waitingCallers--;
                    }
                    continue;
                }
                watching = true;
                watched = true;
                mayWatch = false;
                watchFrom = tailSeq;
            }
            watchForOffer(watchFrom);
        }
    }

    /** Nothing waits, nothing is wrong, and a value offered now could go at once. */
    private boolean idleWithRoom() {
        return sendSeq == tailSeq && !broken && inFlight < (probing ? 1 : settings.window());
    }

    /**
     * Outside the lock: returns as soon as a value is offered after {@code watchFrom}, or after
     * {@code spinMicros}. Yields on every turn, so on a busy machine the watch gives its core to whoever
     * needs it rather than starving the threads that produce the next value.
     */
    private void watchForOffer(long watchFrom) {
        long deadline = System.nanoTime() + settings.spinMicros() * 1_000L;
        while (offered == watchFrom && System.nanoTime() < deadline) {
            Thread.onSpinWait();
            Thread.yield();
        }
    }

    /** Under the lock: the next batch, cut where the origin stream or its numbering changes. */
    private Batch takeBatch(boolean sentDirectly) {
        int max = (int) Math.min(tailSeq - sendSeq, settings.batchMax());
        int first = (int) (sendSeq & mask);
        String originStream = originStreams[first];
        long originFirstSeq = originSeqs[first];
        int n = 1;
        while (n < max) {
            int slot = (int) ((sendSeq + n) & mask);
            if (!originStreams[slot].equals(originStream) || originSeqs[slot] != originFirstSeq + n) {
                break;
            }
            n++;
        }
        Object[] values = new Object[n];
        for (int i = 0; i < n; i++) {
            values[i] = ring[(int) ((sendSeq + i) & mask)];
        }
        Batch batch = new Batch(sink, generation, sendSeq, originStream, originFirstSeq, values, sentDirectly);
        sendSeq += n;
        inFlight++;
        if (sentDirectly) {
            directPending = batch;
            directCalls++;
            int timeout = direct.replyTimeoutMillis();
            directDeadlineNanos = System.nanoTime() + (timeout > 0 ? timeout : Integer.MAX_VALUE) * 1_000_000L;
        }
        return batch;
    }

    /** One call's worth: consecutive values of one origin stream, for the sink of one generation. */
    private record Batch(ValueSink target, long generation, long firstSeq, String originStream, long originFirstSeq,
                         Object[] values, boolean sentDirectly) {
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

    private ValueBatch delivery(Batch batch) {
        Object[] values = batch.values();
        Value[] encoded = new Value[values.length];
        for (int i = 0; i < values.length; i++) {
            encoded[i] = ValueCodec.encode(values[i]);
        }
        return new ValueBatch(id, batch.firstSeq(), batch.originStream(), batch.originFirstSeq(), encoded);
    }

    private void call(Batch batch) {
        ValueBatch delivery = delivery(batch);
        long expected;
        String failure;
        long callStarted = System.nanoTime();
        try {
            expected = LinkFaults.deliver(() -> batch.target().deliver(delivery));
            failure = null;
        } catch (UnknownLink | SystemException e) {
            expected = -1;
            failure = DirectDelivery.failure(e, id);
        }
        long callMillis = (System.nanoTime() - callStarted) / 1_000_000;
        synchronized (lock) {
            longestCallMillis = Math.max(longestCallMillis, callMillis);
        }
        settle(batch, expected, failure);
    }

    /** A call's outcome: acknowledges its values, or breaks the link and rewinds it ({@code failure != null}). */
    private void settle(Batch batch, long expected, String failure) {
        boolean restored = false;
        boolean newlyBroken = false;
        synchronized (lock) {
            if (batch.sentDirectly()) {
                if (directPending != batch) {
                    return; // settled already: its deadline passed, or the link was re-pointed
                }
                directPending = null;
            }
            if (batch.generation() == generation) {
                inFlight--;
                if (failure == null) {
                    acknowledge(expected);
                    lastReplyNanos = System.nanoTime();
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
        DirectDelivery last;
        DirectCallWatch.forget(this);
        synchronized (lock) {
            closed = true;
            last = direct;
            direct = null;
            lock.notifyAll();
        }
        if (last != null) {
            last.close();
        }
        for (Thread t : callers) {
            t.interrupt();
        }
    }
}
