package org.fdnet.logger.writer;

import java.sql.Connection;
import java.sql.SQLException;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.store.EventStore;
import org.fdnet.logger.store.NodeMapping;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One writer connection and the one thread that uses it. {@link #write} COPYs a batch in a new transaction,
 * then waits for the batch before it ({@code before}) and commits only when that one committed — or rolls
 * back when it did not. So with several lanes the COPYs run on several backends at once while the commits
 * stay in batch order. The connection is opened when first needed and closed after any failure (the next
 * batch opens a fresh one).
 */
final class WriterLane implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(WriterLane.class);

    /** A batch rolled back because the batch before it was not committed. */
    static final class RolledBackBehindFailure extends Exception {
        RolledBackBehindFailure() {
            super("rolled back: the batch before it failed", null, false, false);
        }
    }

    private final EventStore store;
    private final ExecutorService thread;
    private Connection connection; // used on the lane's thread only
    private volatile Thread worker;
    private volatile int priority;

    WriterLane(EventStore store, String name, int priority) {
        this.store = store;
        this.priority = priority;
        this.thread = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, name);
            t.setDaemon(true);
            t.setPriority(priority);
            worker = t;
            return t;
        });
    }

    /**
     * Sets the priority of the lane's thread, which sorts, COPYs and COMMITs the batches (the thesis's writer
     * priority must land here, not only on the thread that hands batches out).
     */
    void priority(int wanted) {
        priority = wanted;
        Thread t = worker;
        if (t != null && t.getPriority() != wanted) {
            t.setPriority(wanted);
        }
    }

    /** Opens the connection now (completes exceptionally when the database cannot be reached). */
    CompletableFuture<Void> connect() {
        CompletableFuture<Void> done = new CompletableFuture<>();
        thread.execute(() -> {
            try {
                connection();
                done.complete(null);
            } catch (SQLException | RuntimeException e) {
                done.completeExceptionally(e);
            }
        });
        return done;
    }

    /**
     * Writes {@code batch} (with {@code mappings}) in one transaction: COPY now, COMMIT once {@code before}
     * completed normally. Completes normally when committed; exceptionally with the {@link SQLException}
     * (or runtime failure) that stopped it, or with {@link RolledBackBehindFailure}.
     */
    CompletableFuture<Void> write(List<CachedEvent> batch, List<NodeMapping> mappings, CompletableFuture<Void> before) {
        CompletableFuture<Void> done = new CompletableFuture<>();
        thread.execute(() -> {
            try {
                Connection c = connection();
                EventStore.OpenBatch open = store.copyBatch(c, batch, mappings);
                if (!succeeded(before)) {
                    rollBack(c);
                    done.completeExceptionally(new RolledBackBehindFailure());
                    return;
                }
                store.commitBatch(c, open);
                done.complete(null);
            } catch (SQLException | RuntimeException e) {
                closeConnection();
                done.completeExceptionally(e);
            }
        });
        return done;
    }

    private static boolean succeeded(CompletableFuture<Void> before) {
        boolean interrupted = false;
        try {
            while (true) {
                try {
                    before.get();
                    return true;
                } catch (InterruptedException e) {
                    interrupted = true; // the batch before always completes: wait for it
                } catch (Exception e) {
                    return false;
                }
            }
        } finally {
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private void rollBack(Connection c) {
        try {
            store.rollback(c);
        } catch (SQLException e) {
            LOG.debug("rolling back a batch behind a failed one: {}; closing its connection", e.getMessage());
            closeConnection();
        }
    }

    private Connection connection() throws SQLException {
        if (connection == null) {
            connection = store.openWriterConnection();
        }
        return connection;
    }

    private void closeConnection() {
        if (connection != null) {
            try {
                connection.close();
            } catch (SQLException e) {
                LOG.debug("closing a writer connection: {}", e.getMessage());
            }
            connection = null;
        }
    }

    /** Closes the connection after any batch already handed over, and ends the thread. */
    @Override
    public void close() {
        thread.execute(this::closeConnection);
        thread.shutdown();
        try {
            if (!thread.awaitTermination(30, TimeUnit.SECONDS)) {
                LOG.warn("a writer connection's thread did not end within 30 s");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
