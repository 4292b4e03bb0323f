package org.fdnet.corba;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicInteger;
import org.fdnet.corba.idl.UnknownLink;
import org.fdnet.corba.idl.Value;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.corba.idl.ValueSink;
import org.omg.CORBA.SystemException;
import org.omg.CORBA.portable.ObjectImpl;
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
 * answered within the last {@value #AHEAD_AFTER_REPLY_MILLIS} ms, the value the only one waiting — the writer
 * sends that value <em>ahead</em> itself, as a one-way {@code deliverAhead}: a lone value pays neither for waking a
 * sender thread nor for a reply on the way back. A value sent ahead stays in the ring until the reply of a
 * {@code deliver} covers it: when nothing else goes, a sender thread confirms what went ahead
 * {@value #AHEAD_CONFIRM_MILLIS} ms after the first of it (or once {@value #AHEAD_CONFIRM_VALUES} values went ahead),
 * sending it again as one two-way call (the peer skips what it has applied, and applies what was lost). A
 * confirmation that fails breaks the link like any call. Values closer together than
 * {@link #AHEAD_SPACING_NANOS} are a burst and go through the sender threads in batches.
 *
 * <pre>
 *   offer(v), link idle ──▶ deliverAhead(v) (one-way, writer's thread)     …  v stays in the ring
 *   AHEAD_CONFIRM_MILLIS later, a sender thread ──▶ deliver([headSeq, sendSeq)) ──▶ reply: headSeq moves
 * </pre>
 *
 * Everything else goes through the {@code window} sender threads, and one caller of an idle link may watch for the
 * next value for {@link LinkSettings#spinMicros()} before it parks.
 */
public final class OutboundLink implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(OutboundLink.class);
    private static final AtomicInteger THREADS = new AtomicInteger();
    /** The longest a writer waits for room while the peer acknowledges nothing. */
    public static final long MAX_WRITER_WAIT_MILLIS = 2_000;
    /**
     * A lone value goes ahead from the writer's thread only this soon after the peer last answered: the ORB closes
     * a connection that received nothing for its call timeout ({@link OrbSettings}), and a call on a closed one
     * would open a new connection — a connect that may take the connect timeout — on the writer's thread.
     */
    static final long AHEAD_AFTER_REPLY_MILLIS = 1_000;
    /** How long after the first value sent ahead a sender thread confirms what went ahead (see the class comment). */
    static final long AHEAD_CONFIRM_MILLIS = 20;
    /** How many values sent ahead a sender thread confirms at once, even before {@link #AHEAD_CONFIRM_MILLIS}. */
    static final int AHEAD_CONFIRM_VALUES = 32;
    /**
     * The most values sent ahead and not yet covered by a reply; past it values go through the sender threads. It
     * bounds what one confirmation sends again, the one-way requests the peer's ORB may have queued from one link,
     * and the bytes a silent peer can leave in the connection's buffers.
     */
    static final int AHEAD_MAX = 2 * AHEAD_CONFIRM_VALUES;
    /**
     * A value goes ahead only this long after the send of the last one that did returned: values closer together are
     * a burst, which the sender threads carry in batches (one call for many values) instead of one one-way call each.
     */
    static final long AHEAD_SPACING_NANOS = 10_000;

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
    /** Whether the sink is a peer in another process: only then does a lone value go ahead (one in this ORB is called in place). */
    private boolean aheadPossible;
    /** When the first value sent ahead and not yet covered by a reply went; 0: a reply covers everything sent. */
    private long aheadSinceNanos;
    /** When the last value sent ahead was on the wire (its send returned): a burst is told from it. */
    private volatile long lastAheadNanos;
    private long aheadSends;
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
        this.aheadPossible = inAnotherProcess(sink);
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
        Batch ahead = null;
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
            if (mayGoAhead()) {
                boolean firstAhead = aheadSinceNanos == 0;
                ahead = takeAhead();
                if ((firstAhead || sendSeq - headSeq == AHEAD_CONFIRM_VALUES) && waitingCallers > 0) {
                    lock.notify(); // a sender thread starts the confirmation's clock, or confirms now
                }
            } else if (waitingCallers > 0 && !watching) {
                if (writerWaiting) {
                    lock.notifyAll();
                } else {
                    lock.notify();
                }
            }
        }
        if (ahead != null) {
            sendAhead(ahead);
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
            aheadPossible = inAnotherProcess(newSink);
            generation++;
            inFlight = 0; // calls to the old sink no longer count against the window
            sendSeq = headSeq;
            aheadSinceNanos = 0;
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

    /** Values the writers' threads sent ahead themselves (an idle link's lone values). */
    public long aheadSends() {
        synchronized (lock) {
            return aheadSends;
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

    /** Under the lock: the link is idle, so the value just offered may go ahead from the writer's thread. */
    private boolean mayGoAhead() {
        if (!aheadPossible || inFlight != 0 || probing || broken || sendSeq != tailSeq - 1
                || sendSeq - headSeq >= AHEAD_MAX || LinkFaults.armed()) {
            return false;
        }
        long now = System.nanoTime();
        return now - lastReplyNanos < AHEAD_AFTER_REPLY_MILLIS * 1_000_000L && now - lastAheadNanos >= AHEAD_SPACING_NANOS;
    }

    /** Under the lock: the one value waiting, sent ahead; it stays unacknowledged until a reply covers it. */
    private Batch takeAhead() {
        Batch batch = takeBatch(sendSeq, tailSeq, false);
        sendSeq = tailSeq;
        aheadSends++;
        if (aheadSinceNanos == 0) {
            aheadSinceNanos = System.nanoTime();
        }
        return batch;
    }

    /** Outside the lock, on the writer's thread: a one-way call, back as soon as the request is written. */
    private void sendAhead(Batch batch) {
        try {
            batch.target().deliverAhead(delivery(batch));
            // from the end of the send: a writer whose next value comes while this one was being sent is a burst
            lastAheadNanos = System.nanoTime();
        } catch (SystemException e) {
            settle(batch, -1, failureOf(e, id));
        }
    }

    /** What a failed call says, the same words whether it went ahead or from a sender thread. */
    private static String failureOf(Exception e, long link) {
        if (e instanceof UnknownLink) {
            return "the peer does not know link " + link + " (it restarted and is not re-wired yet)";
        }
        return e.getClass().getSimpleName() + " " + e.getMessage();
    }

    /** Whether {@code sink} is a JacORB reference to another process. */
    private static boolean inAnotherProcess(ValueSink sink) {
        return sink instanceof ObjectImpl stub && stub._get_delegate() instanceof org.jacorb.orb.Delegate
                && !stub._is_local();
    }

    /**
     * Under the lock: values went ahead and no reply has moved {@link #headSeq} for {@value #AHEAD_CONFIRM_MILLIS} ms
     * since — nothing else went to cover them, or one of them was lost and the peer holds back what came after it —
     * or {@value #AHEAD_CONFIRM_VALUES} of them wait for a reply.
     */
    private boolean confirmationDue() {
        if (aheadSinceNanos == 0 || broken || probing || headSeq == sendSeq || inFlight >= settings.window()) {
            return false;
        }
        // with nothing in flight, every value not yet acknowledged went ahead
        return inFlight == 0 && sendSeq - headSeq >= AHEAD_CONFIRM_VALUES
                || System.nanoTime() - aheadSinceNanos >= AHEAD_CONFIRM_MILLIS * 1_000_000L;
    }

    /** Under the lock: how long a parked caller may wait before a confirmation is due; 0 when none is waited for. */
    private long confirmationWaitMillis() {
        if (aheadSinceNanos == 0 || broken) {
            return 0;
        }
        long dueIn = AHEAD_CONFIRM_MILLIS * 1_000_000L - (System.nanoTime() - aheadSinceNanos);
        return Math.max(1, (dueIn + 999_999) / 1_000_000);
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
                if (confirmationDue()) {
                    aheadSinceNanos = System.nanoTime(); // the next confirmation, if this one's reply does not cover all
                    return takeBatch(headSeq, sendSeq, true); // sends again what went ahead: the reply covers it
                }
                if (readyToSend()) {
                    Batch batch = takeBatch(sendSeq, tailSeq, true);
                    sendSeq += batch.values().length;
                    if (waitingCallers > 0 && readyToSend()) {
                        lock.notify(); // values offered during a watch were not announced: share them out
                    }
                    return batch;
                }
                if (watching || !mayWatch || !idleWithRoom() || settings.spinMicros() == 0) {
                    waitingCallers++;
                    try {
                        lock.wait(broken ? settings.retryMillis() : confirmationWaitMillis());
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

    /**
     * Under the lock: the values from {@code from} (at most up to {@code limit}) as one batch, cut where the origin
     * stream or its numbering changes; a two-way call's batch counts against the window.
     */
    private Batch takeBatch(long from, long limit, boolean twoWay) {
        int max = (int) Math.min(limit - from, settings.batchMax());
        int first = (int) (from & mask);
        String originStream = originStreams[first];
        long originFirstSeq = originSeqs[first];
        int n = 1;
        while (n < max) {
            int slot = (int) ((from + n) & mask);
            if (!originStreams[slot].equals(originStream) || originSeqs[slot] != originFirstSeq + n) {
                break;
            }
            n++;
        }
        Object[] values = new Object[n];
        for (int i = 0; i < n; i++) {
            values[i] = ring[(int) ((from + i) & mask)];
        }
        if (twoWay) {
            inFlight++;
        }
        return new Batch(sink, generation, from, originStream, originFirstSeq, values, twoWay);
    }

    /** One call's worth: consecutive values of one origin stream, for the sink of one generation. */
    private record Batch(ValueSink target, long generation, long firstSeq, String originStream, long originFirstSeq,
                         Object[] values, boolean twoWay) {
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
            failure = failureOf(e, id);
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
            if (batch.generation() == generation) {
                if (batch.twoWay()) {
                    inFlight--;
                }
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
                    aheadSinceNanos = 0; // what went ahead is sent again from headSeq once the peer answers
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
        boolean progress = upTo > headSeq;
        if (progress) {
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
        if (aheadSinceNanos != 0 && progress) {
            // all covered: the clock stops; some not yet (sent while this call flew): it starts again. Without
            // progress it runs on, so a value lost ahead is sent again even while other calls keep replying.
            aheadSinceNanos = headSeq == sendSeq ? 0 : System.nanoTime();
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
