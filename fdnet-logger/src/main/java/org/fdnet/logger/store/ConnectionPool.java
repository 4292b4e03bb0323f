package org.fdnet.logger.store;

import java.sql.Connection;
import java.sql.SQLException;
import java.util.ArrayDeque;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A few database connections for viewer queries, so 100 viewers do not open 100 connections. Borrow with
 * {@link #borrow}, give back with {@link #giveBack} (pass {@code broken} when the connection failed: it is
 * closed instead of reused, and so are the idle ones: a connection breaks mostly because the server restarted,
 * and then every idle one is dead too — handing them out one by one made a writer spend its reconnect attempts
 * on dead connections after PostgreSQL came back, found by {@code fdnet soak}). Hazard: a connection not given
 * back is a permit lost.
 */
public final class ConnectionPool implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(ConnectionPool.class);
    private final DatabaseTarget target;
    private final Semaphore permits;
    private final ArrayDeque<Connection> idle = new ArrayDeque<>();

    public ConnectionPool(DatabaseTarget target, int size) {
        this.target = target;
        this.permits = new Semaphore(size, true);
    }

    public Connection borrow() throws SQLException {
        try {
            if (!permits.tryAcquire(30, TimeUnit.SECONDS)) {
                throw new SQLException("no database connection free within 30 s");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new SQLException("interrupted waiting for a database connection", e);
        }
        try {
            Connection c;
            synchronized (idle) {
                c = idle.pollFirst();
            }
            return c != null ? c : target.open();
        } catch (SQLException | RuntimeException e) {
            permits.release();
            throw e;
        }
    }

    public void giveBack(Connection c, boolean broken) {
        try {
            if (broken) {
                close(c);
                synchronized (idle) {
                    idle.forEach(ConnectionPool::close);
                    idle.clear();
                }
            } else {
                synchronized (idle) {
                    idle.addLast(c);
                }
            }
        } finally {
            permits.release();
        }
    }

    private static void close(Connection c) {
        try {
            c.close();
        } catch (SQLException e) {
            LOG.debug("closing a broken connection: {}", e.getMessage());
        }
    }

    @Override
    public void close() {
        synchronized (idle) {
            idle.forEach(ConnectionPool::close);
            idle.clear();
        }
    }
}
