package org.fdnet.logger.writer;

import java.sql.SQLException;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.store.EventStore;
import org.fdnet.logger.store.NodeMapping;
import org.fdnet.logger.store.SourceDirectory;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The writer thread (thesis, chapter 4 VII B–C): empties the cache into the database in batches — when
 * {@code batchSize} events are ready, or when the timer ({@code batchTimeoutMillis}) runs out with fewer —
 * each batch in one COPY transaction; when more are waiting, the batch takes more of them (growing with the
 * backlog up to {@code writer.maxBatchRows} / {@code writer.maxBatchMegabytes}, see {@link BatchSizer}); events leave the cache only after the commit. At the cache's critical
 * level, or when a viewer asks for a flush, it writes back to back (and, if enabled, at maximum thread
 * priority) until the normal level.
 *
 * <p>Several connections ({@code writer.connections}): under backlog, while batch N is COPYed or committed on
 * one connection, batch N+1 is COPYed on another (a second backend, a second core); N+1's watermark and COMMIT
 * are sent only once N's COMMIT returned ({@link WriterLane}), so each run's committed events stay a prefix
 * of its sequence numbers, and events leave the cache and are acknowledged batch after batch, in order. If N
 * fails, N+1 is rolled back and both are written again in order, one at a time. A batch carrying new node
 * mappings or names is written only when nothing else is in flight (the one way two open transactions could
 * lock each other's rows); the connections' lock timeout turns any other such wait into a failure and retry.
 * To keep every lane busy when clients can only have so many events unacknowledged, a free lane gets the
 * next batch — what is ready — as soon as {@link BatchSizer#pipelineFloor()} events are ready. At low load
 * (fewer ready while one is in flight) the in-flight batch commits first, so the thesis's batch size and
 * timer keep their meaning.
 *
 * <p>Database lost: the same batch is retried every {@code reconnectDelayMillis}, each retry on a fresh
 * connection; after {@code reconnectAttempts} failed reconnections (the thesis panel's "number of attempts":
 * N attempts are N reconnections, the failed write that lost the database is not one of them) it reports the
 * database DOWN and stops retrying until told to ({@link #retryDatabase()}) — nothing is dropped meanwhile: the cache
 * keeps accepting until its critical level, then the receivers push back on the cores, whose caches and
 * journals keep everything not acknowledged. With {@code reconnect=false} the writer gives up at the first
 * loss and stops the logger (the cores still hold every unacknowledged event).
 */
public final class BatchWriter implements Runnable {
    private static final Logger LOG = LoggerFactory.getLogger(BatchWriter.class);
    /** How often a writer waiting to fill a free lane looks whether the batch in flight committed. */
    private static final long POLL_NANOS = TimeUnit.MILLISECONDS.toNanos(2);

    private volatile WriterSettings settings;
    private final EventCache cache;
    private final EventStore store;
    private final SourceDirectory directory;
    private final Runnable onGiveUp;
    private final AtomicLong flushTarget = new AtomicLong();
    private volatile boolean stopping;
    private volatile boolean drainOnStop = true;
    private volatile String databaseState = "connecting";
    private volatile long batches;
    private volatile long overlappedBatches;
    private volatile long overlappedRows;
    private volatile long rolledBackBehind;
    private volatile long reconnectionAttempts;
    private final LongAdder laneBusyNanos = new LongAdder();
    private volatile int lastBatchRows;
    private volatile BatchObserver observer;
    private final BatchSizer sizer;
    private final Object retrySignal = new Object();
    private boolean retryRequested; // guarded by retrySignal
    private final WriterLane[] lanes;
    private final Deque<InFlight> inFlight = new ArrayDeque<>();
    private int nextLane;

    /** A batch handed to a lane, not yet known committed. */
    private record InFlight(List<CachedEvent> batch, CompletableFuture<Void> done) {
    }

    public BatchWriter(WriterSettings settings, EventCache cache, EventStore store, SourceDirectory directory,
                       Runnable onGiveUp) {
        this.settings = settings;
        this.cache = cache;
        this.store = store;
        this.directory = directory;
        this.onGiveUp = onGiveUp;
        this.lanes = new WriterLane[Math.max(1, settings.connections())];
        for (int i = 0; i < lanes.length; i++) {
            lanes[i] = new WriterLane(store, "fdnet-writer-connection-" + (i + 1),
                    bulkPriority(settings.priorityEnabled(), false));
        }
        this.sizer = new BatchSizer(settings.batchSize(), settings.maxBatchRows(), lanes.length);
    }

    /**
     * Takes new values of the live settings (writing delay, batch timeout, reconnection attempts and delay) from
     * the next wait on; the lanes, the batch sizer and the priority keep what they were started with.
     */
    public void retune(WriterSettings next) {
        settings = next;
    }

    /** The settings the writer works with now. */
    public WriterSettings settings() {
        return settings;
    }

    /**
     * The Java priority of the threads that write: the maximum at the critical level with {@code priority.enabled},
     * else normal. (Tried in session 6: the minimum below the critical level, nice 4 as root — on a machine with
     * other work at nice 0 the writer then got too little of the CPU: bench logger's sustained rate fell from
     * 735,000 to 330,000-420,000 events/s under the same load.)
     */
    public static int bulkPriority(boolean enabled, boolean critical) {
        return enabled && critical ? Thread.MAX_PRIORITY : Thread.NORM_PRIORITY;
    }

    /** The writer's connections to the database ({@code writer.connections}). */
    public int connections() {
        return lanes.length;
    }

    /** Events in the last batch taken (it grows with the backlog, see {@link BatchSizer}). */
    public int lastBatchRows() {
        return lastBatchRows;
    }

    /** Sets (or with null removes) the one observer told of each committed batch. */
    public void observe(BatchObserver observer) {
        this.observer = observer;
    }

    /** The most events one batch may take ({@code writer.maxBatchRows}, at least the batch size). */
    public int maxBatchRows() {
        return sizer.maxRows();
    }

    /** "connected", or since when and how often the database failed. */
    public String databaseState() {
        return databaseState;
    }

    public long batches() {
        return batches;
    }

    /** Batches handed to a connection while the one before was still in flight (the pipeline at work). */
    public long overlappedBatches() {
        return overlappedBatches;
    }

    /** Events in the batches counted by {@link #overlappedBatches()}. */
    public long overlappedRows() {
        return overlappedRows;
    }

    /**
     * Time the lanes spent on batches, summed over the lanes (from a batch handed to its lane until its
     * outcome, the wait for the batch before it included): divided by {@code connections() x} a period, how
     * busy the lanes were.
     */
    public long laneBusyNanos() {
        return laneBusyNanos.sum();
    }

    /** Batches rolled back because the batch before them failed (each then written again, in order). */
    public long rolledBackBehind() {
        return rolledBackBehind;
    }

    /**
     * Writes everything received so far (the thesis's rule before a viewer is answered from the database);
     * true when done within the timeout.
     */
    public boolean flush(long timeoutMillis) {
        long target = cache.received();
        flushTarget.accumulateAndGet(target, Math::max);
        cache.wake();
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMillis);
        while (cache.committedCount() < target) {
            if (System.nanoTime() > deadline) {
                return false;
            }
            try {
                Thread.sleep(1);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return false;
            }
        }
        return true;
    }

    /** Stops after writing what the cache holds (when {@code drain}) or after the current batch. */
    public void stop(boolean drain) {
        drainOnStop = drain;
        stopping = true;
        cache.wake();
        synchronized (retrySignal) {
            retrySignal.notifyAll();
        }
    }

    /** Attempts to reach the database again after a failed write (each one after {@code reconnectDelayMillis}). */
    public long reconnectionAttempts() {
        return reconnectionAttempts;
    }

    /** Tells a writer that reported the database down to try again (another round of attempts). */
    public void retryDatabase() {
        synchronized (retrySignal) {
            retryRequested = true;
            retrySignal.notifyAll();
        }
    }

    /** Waits until {@link #retryDatabase()} or a stop; true when told to retry. */
    private boolean awaitRetryRequest() throws InterruptedException {
        synchronized (retrySignal) {
            while (!retryRequested && !stopping) {
                retrySignal.wait();
            }
            boolean retry = retryRequested;
            retryRequested = false;
            return retry;
        }
    }

    @Override
    public void run() {
        long timerStart = System.nanoTime();
        try {
            for (WriterLane lane : lanes) {
                lane.connect().get();
            }
            databaseState = "connected";
        } catch (ExecutionException e) {
            databaseState = "unreachable: " + e.getCause().getMessage();
            LOG.warn("writer cannot reach the database yet ({}); it will retry with the first batch",
                    e.getCause().getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            closeLanes();
            return;
        }
        try {
            while (true) {
                if (!reapCommitted()) {
                    break;
                }
                if (inFlight.size() == lanes.length) {
                    if (!finishOldest()) {
                        break;
                    }
                    continue;
                }
                boolean urgent = cache.pressured() || flushTarget.get() > cache.committedCount() || stopping;
                if (stopping && (!drainOnStop || cache.unwrittenCount() == 0)) {
                    break;
                }
                priority(cache.pressured());
                long delay = urgent ? 0 : TimeUnit.MILLISECONDS.toNanos(settings.writingDelayMillis());
                if (!inFlight.isEmpty() && !batchReadyNow(urgent, delay)) {
                    // A lane is free while another writes: wait for the floor's worth of events, looking every
                    // POLL for the batch in flight to commit. At low load it commits first and the next batch
                    // is taken by the thesis's batch size and timer, as with one connection.
                    cache.awaitUnwritten(sizer.pipelineFloor(), delay, POLL_NANOS);
                    continue;
                }
                long timerLeft = TimeUnit.MILLISECONDS.toNanos(settings.batchTimeoutMillis()) - (System.nanoTime() - timerStart);
                int ready = cache.awaitUnwritten(settings.batchSize(), delay, urgent ? 0 : Math.max(0, timerLeft));
                boolean timerExpired = System.nanoTime() - timerStart >= TimeUnit.MILLISECONDS.toNanos(settings.batchTimeoutMillis());
                if (ready >= settings.batchSize() || (ready > 0 && (timerExpired || urgent))) {
                    int backlog = delay == 0 ? cache.unwrittenCount() : cache.readyUnwritten(sizer.maxRows(), delay);
                    List<CachedEvent> batch = cache.takeBatch(Math.max(ready, Math.min(backlog, sizer.next(backlog, !inFlight.isEmpty()))),
                            settings.maxBatchBytes());
                    lastBatchRows = batch.size();
                    List<NodeMapping> mappings = directory.unsavedMappings();
                    if (lanes.length == 1 || !mappings.isEmpty() || carriesNames(batch)) {
                        if (!finishAll() || !write(batch, mappings, null)) {
                            break;
                        }
                    } else {
                        dispatch(batch);
                    }
                    timerStart = System.nanoTime();
                } else if (timerExpired) {
                    timerStart = System.nanoTime();
                }
            }
            finishAll();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            closeLanes();
            LOG.info("writer stopped: {} batches, {} events committed, {} unwritten", batches, cache.committedCount(),
                    cache.unwrittenCount());
        }
    }

    /** With a batch in flight: enough ready for a batch on a free lane (the pipeline floor, or any when urgent). */
    private boolean batchReadyNow(boolean urgent, long delay) {
        int floor = sizer.pipelineFloor();
        int ready = cache.readyUnwritten(floor, delay);
        return ready >= floor || (urgent && ready > 0);
    }

    private static boolean carriesNames(List<CachedEvent> batch) {
        for (CachedEvent e : batch) {
            if (e.event() instanceof NodeNamedEvent) {
                return true;
            }
        }
        return false;
    }

    /** Hands a batch to the next lane: its COPY starts now, its COMMIT waits for the batch before it. */
    private void dispatch(List<CachedEvent> batch) {
        CompletableFuture<Void> before = inFlight.isEmpty() ? CompletableFuture.completedFuture(null)
                : inFlight.peekLast().done();
        if (!inFlight.isEmpty()) {
            overlappedBatches++;
            overlappedRows += batch.size();
        }
        WriterLane lane = lanes[nextLane];
        nextLane = (nextLane + 1) % lanes.length;
        inFlight.addLast(new InFlight(batch, timed(lane.write(batch, List.of(), before))));
    }

    /** Counts the lane's time on a batch, from now until its outcome, into {@link #laneBusyNanos()}. */
    private CompletableFuture<Void> timed(CompletableFuture<Void> done) {
        long start = System.nanoTime();
        done.whenComplete((v, e) -> laneBusyNanos.add(System.nanoTime() - start));
        return done;
    }

    /** Finishes the in-flight batches already done (commits seen promptly: ACKs and eviction not delayed). */
    private boolean reapCommitted() throws InterruptedException {
        while (!inFlight.isEmpty() && inFlight.peekFirst().done().isDone()) {
            if (!finishOldest()) {
                return false;
            }
        }
        return true;
    }

    private boolean finishAll() throws InterruptedException {
        while (!inFlight.isEmpty()) {
            if (!finishOldest()) {
                return false;
            }
        }
        return true;
    }

    /**
     * Waits for the oldest batch in flight. Committed: it leaves the cache. Failed: every batch behind it is
     * rolled back by its lane (its COMMIT waited for this one), then all of them are written again, in order,
     * one at a time (with the outage rules of {@link #write}); false only when giving up.
     */
    private boolean finishOldest() throws InterruptedException {
        InFlight oldest = inFlight.pollFirst();
        Throwable failure = outcome(oldest.done());
        if (failure == null) {
            committed(oldest.batch(), List.of());
            return true;
        }
        List<InFlight> behind = new ArrayList<>(inFlight);
        inFlight.clear();
        rolledBackBehind += behind.size();
        for (InFlight b : behind) {
            if (outcome(b.done()) == null) {
                throw new IllegalStateException("a batch committed after the batch before it failed");
            }
        }
        LOG.warn("a batch of {} events failed ({}); {} batch(es) behind it rolled back; writing them again in order",
                oldest.batch().size(), failure.getMessage(), behind.size());
        SQLException cause = failure instanceof SQLException sql ? sql : new SQLException(failure.getMessage(), failure);
        if (!write(oldest.batch(), List.of(), cause)) {
            return false;
        }
        for (InFlight b : behind) {
            if (!write(b.batch(), List.of(), null)) {
                return false;
            }
        }
        return true;
    }

    /** Null when the batch committed, else why not. */
    private static Throwable outcome(CompletableFuture<Void> done) throws InterruptedException {
        try {
            done.get();
            return null;
        } catch (ExecutionException e) {
            return e.getCause();
        }
    }

    /** The batch is in the database: mappings saved, events out of the cache (cores acknowledged), observer told. */
    private void committed(List<CachedEvent> batch, List<NodeMapping> mappings) {
        directory.saved(mappings);
        cache.committed(batch);
        batches++;
        databaseState = "connected";
        BatchObserver o = observer;
        if (o != null) {
            o.committed(batch);
        }
    }

    /** Raises (critical level) or lowers (normal level) every thread that writes: this one and each lane's. */
    private void priority(boolean high) {
        int wanted = bulkPriority(settings.priorityEnabled(), high);
        if (Thread.currentThread().getPriority() != wanted) {
            Thread.currentThread().setPriority(wanted);
        }
        for (WriterLane lane : lanes) {
            lane.priority(wanted);
        }
    }

    /**
     * Writes one batch alone (nothing else in flight), retrying until it is committed; false only when giving
     * up (reconnect=false, or a stop without drain). {@code alreadyFailed}: its first attempt failed in the
     * pipeline (the COMMIT's outcome may be unknown: the next attempt asks the database first).
     */
    private boolean write(List<CachedEvent> batch, List<NodeMapping> mappings, SQLException alreadyFailed)
            throws InterruptedException {
        int failures = 0;
        long downSince = 0;
        SQLException failure = alreadyFailed;
        while (true) {
            if (failure == null) {
                if (failures > 0) {
                    reconnectionAttempts++;
                }
                try {
                    if (failures > 0 && store.wasCommitted(batch)) {
                        LOG.info("the batch whose commit failed was committed after all; not writing it again");
                    } else {
                        awaitCommit(timed(lanes[0].write(batch, mappings, CompletableFuture.completedFuture(null))));
                    }
                    committed(batch, mappings);
                    if (failures > 0) {
                        LOG.warn("database back after {} failed reconnection attempts ({} s); writing resumes",
                                failures - 1, (System.currentTimeMillis() - downSince) / 1000);
                    }
                    return true;
                } catch (SQLException e) {
                    failure = e;
                }
            }
            SQLException e = failure;
            failure = null;
            failures++;
            if (failures == 1) {
                downSince = System.currentTimeMillis();
            }
            int reconnections = failures - 1; // the first failure lost the database; every later one was a retry
            databaseState = "lost since " + Instant.ofEpochMilli(downSince) + ", " + reconnections
                    + " reconnection attempts";
            if (!settings.reconnect()) {
                LOG.error("database {} lost ({}); writer.reconnect=false: stopping the logger. The cores keep their"
                        + " {} unacknowledged events and send them to the next logger.", store.target(), e.getMessage(),
                        cache.unwrittenCount() + batch.size());
                onGiveUp.run();
                return false;
            }
            if (failures == 1) {
                LOG.warn("database write failed ({}); holding {} events, retrying every {} ms", e.getMessage(),
                        cache.unwrittenCount() + batch.size(), settings.reconnectDelayMillis());
            }
            if (reconnections > 0 && reconnections % settings.reconnectAttempts() == 0) {
                databaseState = "DOWN since " + Instant.ofEpochMilli(downSince) + ", " + reconnections
                        + " reconnection attempts; not retrying until told to";
                LOG.error("DATABASE DOWN: {} failed reconnection attempts since {}; holding {} events in the cache ({});"
                                + " not retrying until told to; receivers pause at the critical level and the cores"
                                + " keep the rest — nothing is dropped", reconnections, Instant.ofEpochMilli(downSince),
                        cache.unwrittenCount() + batch.size(), e.getMessage());
                if (!awaitRetryRequest()) {
                    return false;
                }
                LOG.warn("told to retry the database {}: {} more reconnection attempts", store.target(),
                        settings.reconnectAttempts());
                continue;
            }
            if (stopping && !drainOnStop) {
                return false;
            }
            Thread.sleep(settings.reconnectDelayMillis());
        }
    }

    /** Waits for a lane's batch; its failure as an SQLException (a runtime failure wrapped). */
    private static void awaitCommit(CompletableFuture<Void> done) throws SQLException, InterruptedException {
        Throwable failure = outcome(done);
        if (failure instanceof SQLException e) {
            throw e;
        } else if (failure != null) {
            throw new SQLException(failure.getMessage(), failure);
        }
    }

    private void closeLanes() {
        for (WriterLane lane : lanes) {
            lane.close();
        }
    }
}
