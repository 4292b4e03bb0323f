package org.fdnet.viewer.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.SQLException;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.logger.store.EmbeddedDatabase;

/**
 * A real logger on a fresh embedded PostgreSQL, both on free ports of 127.0.0.1, deleted when closed:
 * for {@code fdnet bench viewer} and the viewer's end-to-end tests.
 */
public final class ThrowawayLogger implements AutoCloseable {
    private final Path folder;
    private final EmbeddedDatabase database;
    private final NetworkStateLogger logger;

    public ThrowawayLogger() throws IOException, SQLException {
        folder = Files.createTempDirectory("fdnet-viewer-logger");
        database = EmbeddedDatabase.startThrowaway(folder.resolve("pg"));
        NetworkStateLogger started = null;
        try {
            DatabaseTarget target = database.target();
            LoggerConfig config = new LoggerConfig()
                    .set(LoggerSetting.DATABASE_EMBEDDED, "false").set(LoggerSetting.DATABASE_URL, target.url())
                    .set(LoggerSetting.DATABASE_USER, target.user())
                    .set(LoggerSetting.RECEIVER_PORT, "0").set(LoggerSetting.SENDER_PORT, "0");
            started = new NetworkStateLogger(config);
            started.start();
        } catch (IOException | SQLException | RuntimeException e) {
            if (started != null) {
                started.close();
            }
            database.close();
            throw e;
        }
        logger = started;
    }

    public NetworkStateLogger logger() {
        return logger;
    }

    public int receiverPort() {
        return logger.receiverPort();
    }

    /** {@code 127.0.0.1:PORT} of the viewer (sender) service. */
    public String viewerAddress() {
        return "127.0.0.1:" + logger.senderPort();
    }

    @Override
    public void close() throws IOException {
        try {
            logger.close();
        } finally {
            database.close();
            Files.deleteIfExists(folder);
        }
    }
}
