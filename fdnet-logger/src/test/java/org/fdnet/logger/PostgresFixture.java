package org.fdnet.logger;

import java.io.IOException;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.logger.store.EmbeddedDatabase;
import org.testcontainers.DockerClientFactory;
import org.testcontainers.containers.PostgreSQLContainer;

/**
 * A real PostgreSQL for tests: {@code FDNET_PG_URL} (user {@code FDNET_PG_USER}, default postgres) if set,
 * else a Testcontainers PostgreSQL when Docker runs, else the embedded server in a temporary folder. Each
 * fixture gets its own fresh database. {@link #stopDatabase}/{@link #startDatabase} make a real outage:
 * the embedded server is stopped and started again on the same folder and port; an external or container
 * server refuses connections to the test's database and has its sessions terminated.
 */
public final class PostgresFixture implements AutoCloseable {
    private static int counter;
    private final Path folder;
    private EmbeddedDatabase embedded;
    private PostgreSQLContainer<?> container;
    private final DatabaseTarget admin;
    private final String database;
    private int embeddedPort;

    public PostgresFixture(Path folder) throws IOException, SQLException {
        this.folder = folder;
        String url = System.getenv("FDNET_PG_URL");
        if (url != null && !url.isBlank()) {
            String user = System.getenv().getOrDefault("FDNET_PG_USER", "postgres");
            admin = new DatabaseTarget(url, user, System.getenv().getOrDefault("FDNET_PG_PASSWORD", ""));
        } else if (dockerAvailable()) {
            container = new PostgreSQLContainer<>("postgres:16-alpine");
            container.start();
            admin = new DatabaseTarget(container.getJdbcUrl(), container.getUsername(), container.getPassword());
        } else {
            embedded = EmbeddedDatabase.start(folder.resolve("pg"), 0);
            embeddedPort = embedded.port();
            admin = embedded.target();
        }
        database = "fdnet_test_" + ProcessHandle.current().pid() + "_" + (++counter);
        try (Connection c = admin.open(); Statement s = c.createStatement()) {
            s.execute("CREATE DATABASE " + database);
        }
    }

    private static boolean dockerAvailable() {
        // Ask Testcontainers only where a Docker engine could be: its probe logs a page of errors otherwise.
        if (System.getenv("DOCKER_HOST") == null && !java.nio.file.Files.exists(Path.of("/var/run/docker.sock"))) {
            return false;
        }
        try {
            return DockerClientFactory.instance().isDockerAvailable();
        } catch (RuntimeException | LinkageError e) {
            return false;
        }
    }

    public DatabaseTarget target() {
        String url = admin.url();
        int q = url.indexOf('?');
        String base = q < 0 ? url : url.substring(0, q);
        String params = q < 0 ? "" : url.substring(q);
        return new DatabaseTarget(base.substring(0, base.lastIndexOf('/') + 1) + database + params, admin.user(),
                admin.password());
    }

    /** A logger configuration on this database, free ports, small timers for quick tests. */
    public LoggerConfig loggerConfig() {
        DatabaseTarget t = target();
        return new LoggerConfig().set(LoggerSetting.DATABASE_EMBEDDED, "false").set(LoggerSetting.DATABASE_URL, t.url())
                .set(LoggerSetting.DATABASE_USER, t.user()).set(LoggerSetting.DATABASE_PASSWORD, t.password())
                .set(LoggerSetting.RECEIVER_PORT, "0").set(LoggerSetting.SENDER_PORT, "0")
                .set(LoggerSetting.WRITER_BATCH_TIMEOUT, "200").set(LoggerSetting.WRITER_RECONNECT_DELAY, "200")
                // outage tests expect the writer to retry through the whole outage, not to report it down
                .set(LoggerSetting.WRITER_RECONNECT_ATTEMPTS, "100000");
    }

    public long count(String sql) throws SQLException {
        try (Connection c = target().open(); Statement s = c.createStatement(); ResultSet rs = s.executeQuery(sql)) {
            rs.next();
            return rs.getLong(1);
        }
    }

    /** The first column of the first row of {@code sql}, as text. */
    public String text(String sql) throws SQLException {
        try (Connection c = target().open(); Statement s = c.createStatement(); ResultSet rs = s.executeQuery(sql)) {
            if (!rs.next()) {
                throw new SQLException("no row: " + sql);
            }
            return rs.getString(1);
        }
    }

    public void stopDatabase() throws IOException, SQLException {
        if (embedded != null) {
            embedded.close();
            embedded = null;
        } else {
            try (Connection c = admin.open(); Statement s = c.createStatement()) {
                s.execute("ALTER DATABASE " + database + " ALLOW_CONNECTIONS false");
                s.execute("SELECT pg_terminate_backend(pid) FROM pg_stat_activity WHERE datname = '" + database + "'");
            }
        }
    }

    public void startDatabase() throws IOException, SQLException {
        if (embedded == null && container == null && System.getenv("FDNET_PG_URL") == null) {
            embedded = EmbeddedDatabase.start(folder.resolve("pg"), embeddedPort);
        } else if (embedded == null) {
            try (Connection c = admin.open(); Statement s = c.createStatement()) {
                s.execute("ALTER DATABASE " + database + " ALLOW_CONNECTIONS true");
            }
        }
    }

    @Override
    public void close() throws IOException {
        if (embedded != null) {
            embedded.close();
        }
        if (container != null) {
            container.stop();
        }
    }
}
