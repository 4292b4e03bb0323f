package org.fdnet.logger.writer;

import java.sql.Connection;
import java.sql.SQLException;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
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
 * <p>Database lost: the same batch is retried every {@code reconnectDelayMillis}; after
 * {@code reconnectAttempts} failed attempts (the thesis panel's "number of attempts") it reports the database
 * DOWN and stops retrying until told to ({@link #retryDatabase()}) — nothing is dropped meanwhile: the cache
 * keeps accepting until its critical level, then the receivers push back on the cores, whose caches and
 * journals keep everything not acknowledged. With {@code reconnect=false} the writer gives up at the first
 * loss and stops the logger (the cores still hold every unacknowledged event).
 */
public final class BatchWriter implements Runnable {
    private static final Logger LOG = LoggerFactory.getLogger(BatchWriter.class);

    private final WriterSettings settings;
    private final EventCache cache;
    private final EventStore store;
    private final SourceDirectory directory;
    private final Runnable onGiveUp;
    private final AtomicLong flushTarget = new AtomicLong();
    private volatile boolean stopping;
    private volatile boolean drainOnStop = true;
    private volatile String databaseState = "connecting";
    private volatile long batches;
    private volatile int lastBatchRows;
    private volatile BatchObserver observer;
    private final BatchSizer sizer;
    private final Object retrySignal = new Object();
    private boolean retryRequested; // guarded by retrySignal
    private Connection connection;

    public BatchWriter(WriterSettings settings, EventCache cache, EventStore store, SourceDirectory directory,
                       Runnable onGiveUp) {
        this.settings = settings;
        this.cache = cache;
        this.store = store;
        this.directory = directory;
        this.onGiveUp = onGiveUp;
        this.sizer = new BatchSizer(settings.batchSize(), settings.maxBatchRows());
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
            connection = store.openWriterConnection();
            databaseState = "connected";
        } catch (SQLException e) {
            databaseState = "unreachable: " + e.getMessage();
            LOG.warn("writer cannot reach the database yet ({}); it will retry with the first batch", e.getMessage());
        }
        try {
            while (true) {
                boolean urgent = cache.pressured() || flushTarget.get() > cache.committedCount() || stopping;
                if (stopping && (!drainOnStop || cache.unwrittenCount() == 0)) {
                    break;
                }
                priority(cache.pressured());
                long timerLeft = TimeUnit.MILLISECONDS.toNanos(settings.batchTimeoutMillis()) - (System.nanoTime() - timerStart);
                long delay = urgent ? 0 : TimeUnit.MILLISECONDS.toNanos(settings.writingDelayMillis());
                int ready = cache.awaitUnwritten(settings.batchSize(), delay, urgent ? 0 : Math.max(0, timerLeft));
                boolean timerExpired = System.nanoTime() - timerStart >= TimeUnit.MILLISECONDS.toNanos(settings.batchTimeoutMillis());
                if (ready >= settings.batchSize() || (ready > 0 && (timerExpired || urgent))) {
                    int backlog = delay == 0 ? cache.unwrittenCount() : cache.readyUnwritten(sizer.maxRows(), delay);
                    List<CachedEvent> batch = cache.takeBatch(Math.max(ready, Math.min(backlog, sizer.next(backlog))),
                            settings.maxBatchBytes());
                    lastBatchRows = batch.size();
                    if (!write(batch)) {
                        break;
                    }
                    BatchObserver o = observer;
                    if (o != null) {
                        o.committed(batch);
                    }
                    timerStart = System.nanoTime();
                } else if (timerExpired) {
                    timerStart = System.nanoTime();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            closeConnection();
            LOG.info("writer stopped: {} batches, {} events committed, {} unwritten", batches, cache.committedCount(),
                    cache.unwrittenCount());
        }
    }

    private void priority(boolean high) {
        int wanted = settings.priorityEnabled() && high ? Thread.MAX_PRIORITY : Thread.NORM_PRIORITY;
        if (Thread.currentThread().getPriority() != wanted) {
            Thread.currentThread().setPriority(wanted);
        }
    }

    /** Writes one batch, retrying until it is committed; false only when giving up (reconnect=false). */
    private boolean write(List<CachedEvent> batch) throws InterruptedException {
        List<NodeMapping> mappings = directory.unsavedMappings();
        int failures = 0;
        long downSince = 0;
        while (true) {
            try {
                if (connection == null) {
                    connection = store.openWriterConnection();
                }
                if (failures > 0 && store.wasCommitted(batch)) {
                    LOG.info("the batch whose commit failed was committed after all; not writing it again");
                } else {
                    store.writeBatch(connection, batch, mappings);
                }
                directory.saved(mappings);
                cache.committed(batch);
                batches++;
                if (failures > 0) {
                    LOG.warn("database back after {} failed attempts ({} s); writing resumes",
                            failures, (System.currentTimeMillis() - downSince) / 1000);
                }
                databaseState = "connected";
                return true;
            } catch (SQLException e) {
                closeConnection();
                failures++;
                if (failures == 1) {
                    downSince = System.currentTimeMillis();
                }
                databaseState = "lost since " + Instant.ofEpochMilli(downSince) + ", " + failures + " attempts";
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
                if (failures % settings.reconnectAttempts() == 0) {
                    databaseState = "DOWN since " + Instant.ofEpochMilli(downSince) + ", " + failures
                            + " attempts; not retrying until told to";
                    LOG.error("DATABASE DOWN: {} failed attempts since {}; holding {} events in the cache ({}); not"
                                    + " retrying until told to; receivers pause at the critical level and the cores"
                                    + " keep the rest — nothing is dropped", failures, Instant.ofEpochMilli(downSince),
                            cache.unwrittenCount() + batch.size(), e.getMessage());
                    if (!awaitRetryRequest()) {
                        return false;
                    }
                    LOG.warn("told to retry the database {}: {} more attempts", store.target(),
                            settings.reconnectAttempts());
                    continue;
                }
                if (stopping && !drainOnStop) {
                    return false;
                }
                Thread.sleep(settings.reconnectDelayMillis());
            }
        }
    }

    private void closeConnection() {
        if (connection != null) {
            try {
                connection.close();
            } catch (SQLException e) {
                LOG.debug("closing the writer's connection: {}", e.getMessage());
            }
            connection = null;
        }
    }
}
