package org.fdnet.logger.store;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Lowers the CPU priority of the PostgreSQL backends that COPY the writer's batches, when the database runs on
 * this host ({@code writer.backendNiceness}; 0, off, by default). While the writer drains a backlog its backends
 * are the largest consumers of CPU; on a machine where the database shares the cores with more important work (the
 * network the logger records) a higher nice value makes them step aside. The price, measured in {@code bench
 * logger}: the backends are the logger's bottleneck, and at nice 10 the producer and the receivers took their CPU
 * and the sustained rate halved — hence off by default.
 *
 * <p>How: {@code pg_backend_pid()} of the writer's connection, then {@code renice} (PostgreSQL has no setting for
 * it). Only for a server reached over loopback or a Unix socket: a backend on another host is not ours to touch.
 * A backend of another user (a system PostgreSQL while the logger is not root) cannot be reniced: the first such
 * failure is logged as a warning naming the backend and the reason, later ones at debug level; writing goes on.
 * ({@code bench logger}'s raw-COPY baselines use it too, so that they run at the writer's priorities.)
 */
public final class BackendNiceness {
    private static final Logger LOG = LoggerFactory.getLogger(BackendNiceness.class);
    private static final long RENICE_TIMEOUT_SECONDS = 5;

    private final int niceness;
    private final AtomicBoolean warned = new AtomicBoolean();

    /** @param niceness 0 (leave the backends alone) to 19 */
    public BackendNiceness(int niceness) {
        if (niceness < 0 || niceness > 19) {
            throw new IllegalArgumentException("writer.backendNiceness must be 0 to 19, was " + niceness);
        }
        this.niceness = niceness;
    }

    /** Applies the nice value to the backend serving {@code c}, if it is on this host; never throws. */
    public void apply(Connection c) {
        if (niceness == 0) {
            return;
        }
        long pid;
        try (Statement st = c.createStatement();
             ResultSet rs = st.executeQuery("SELECT pg_backend_pid(), coalesce(host(inet_server_addr()), 'local')")) {
            rs.next();
            pid = rs.getLong(1);
            String server = rs.getString(2);
            if (!isThisHost(server)) {
                LOG.debug("writer backend {} runs on {}, not this host: its priority is left alone", pid, server);
                return;
            }
        } catch (SQLException e) {
            failed("the writer's backend", "cannot ask for its process id: " + e.getMessage());
            return;
        }
        renice(pid);
    }

    private static boolean isThisHost(String server) {
        return server.equals("local") || server.startsWith("127.") || server.equals("::1");
    }

    private void renice(long pid) {
        try {
            Process p = new ProcessBuilder("renice", "-n", Integer.toString(niceness), "-p", Long.toString(pid))
                    .redirectErrorStream(true).start();
            if (!p.waitFor(RENICE_TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                failed("PostgreSQL backend " + pid, "renice did not finish within " + RENICE_TIMEOUT_SECONDS + " s");
                return;
            }
            String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
            if (p.exitValue() != 0) {
                failed("PostgreSQL backend " + pid, "renice: " + output);
                return;
            }
            LOG.debug("writer backend {} now runs at nice {}", pid, niceness);
        } catch (IOException e) {
            failed("PostgreSQL backend " + pid, "cannot run renice: " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void failed(String what, String why) {
        if (warned.compareAndSet(false, true)) {
            LOG.warn("writer.backendNiceness {}: could not lower the priority of {} ({}); the writer goes on at the"
                    + " backend's own priority, and viewers' queries may wait behind it while it drains", niceness, what, why);
        } else {
            LOG.debug("could not lower the priority of {}: {}", what, why);
        }
    }
}
