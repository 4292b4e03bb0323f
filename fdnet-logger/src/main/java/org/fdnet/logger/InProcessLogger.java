package org.fdnet.logger;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.SQLException;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerConfigFile;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.logger.store.EmbeddedDatabase;

/**
 * A network state logger started in this process, for a command or a test that records what it runs: either on a
 * fresh embedded PostgreSQL deleted when closed ({@link #throwaway()}: {@code fdnet bench viewer}, the viewer's and
 * editor's end-to-end tests), or on the user's database, the same as {@code fdnet logger} reads from
 * ~/.fdnet/logger.properties ({@link #ofUserConfig}: {@code fdnet demo}, {@code fdnet bench roq}). Cores always
 * reach it on a free port of its receiver.
 */
public final class InProcessLogger implements AutoCloseable {
    private final NetworkStateLogger logger;
    private final EmbeddedDatabase throwawayDatabase;
    private final Path throwawayFolder;

    private InProcessLogger(NetworkStateLogger logger, EmbeddedDatabase throwawayDatabase, Path throwawayFolder) {
        this.logger = logger;
        this.throwawayDatabase = throwawayDatabase;
        this.throwawayFolder = throwawayFolder;
    }

    /** A logger on a fresh embedded PostgreSQL in a temporary folder, both on free ports of 127.0.0.1. */
    public static InProcessLogger throwaway() throws IOException, SQLException {
        Path folder = Files.createTempDirectory("fdnet-logger");
        EmbeddedDatabase database = EmbeddedDatabase.startThrowaway(folder.resolve("pg"));
        try {
            DatabaseTarget target = database.target();
            LoggerConfig config = new LoggerConfig()
                    .set(LoggerSetting.DATABASE_EMBEDDED, "false").set(LoggerSetting.DATABASE_URL, target.url())
                    .set(LoggerSetting.DATABASE_USER, target.user())
                    .set(LoggerSetting.RECEIVER_PORT, "0").set(LoggerSetting.SENDER_PORT, "0");
            return new InProcessLogger(started(config), database, folder);
        } catch (IOException | SQLException | RuntimeException e) {
            database.close();
            throw e;
        }
    }

    /**
     * A logger on the user's configured database; with {@code standardViewerPort} viewers reach it on the standard
     * viewer port (5556, what {@code fdnet viewer} assumes) when that is free, else on a free one.
     */
    public static InProcessLogger ofUserConfig(boolean standardViewerPort) throws IOException, SQLException {
        LoggerConfig config = LoggerConfigFile.load(LoggerConfigFile.defaultPath());
        String standard = LoggerSetting.SENDER_PORT.defaultValue();
        boolean useStandard = standardViewerPort && isFree(config.senderAddress(), Integer.parseInt(standard));
        config.set(LoggerSetting.RECEIVER_PORT, "0").set(LoggerSetting.SENDER_PORT, useStandard ? standard : "0");
        return new InProcessLogger(started(config), null, null);
    }

    /** A logger on the database {@code config} names (embedded or external); the caller owns the config's ports. */
    public static InProcessLogger of(LoggerConfig config) throws IOException, SQLException {
        return new InProcessLogger(started(config), null, null);
    }

    private static NetworkStateLogger started(LoggerConfig config) throws IOException, SQLException {
        NetworkStateLogger logger = new NetworkStateLogger(config);
        try {
            logger.start();
        } catch (IOException | SQLException | RuntimeException e) {
            logger.close();
            throw e;
        }
        return logger;
    }

    public NetworkStateLogger logger() {
        return logger;
    }

    /** The port cores send their events to (on the configured receiver address). */
    public int receiverPort() {
        return logger.receiverPort();
    }

    /** {@code HOST:PORT} where viewers reach this logger ({@code fdnet viewer --logger}). */
    public String viewerAddress() {
        String host = logger.config().senderAddress();
        return (host.isBlank() || host.equals("0.0.0.0") ? "127.0.0.1" : host) + ":" + logger.senderPort();
    }

    @Override
    public void close() throws IOException {
        try {
            logger.close();
        } finally {
            if (throwawayDatabase != null) {
                throwawayDatabase.close();
                Files.deleteIfExists(throwawayFolder);
            }
        }
    }

    private static boolean isFree(String host, int port) {
        try (ServerSocket probe = new ServerSocket()) {
            probe.bind(new InetSocketAddress(host, port));
            return true;
        } catch (IOException taken) {
            return false;
        }
    }
}
