package org.fdnet.roq.cli;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerConfigFile;
import org.fdnet.logger.config.LoggerSetting;

/**
 * Starts a network state logger in this process (its embedded PostgreSQL, the same database as {@code fdnet logger}:
 * both read ~/.fdnet/logger.properties) for a command that records what it runs: {@code fdnet demo} and
 * {@code fdnet bench roq}.
 */
final class LocalLogger {
    private LocalLogger() {
    }

    /** A started logger on free ports; the caller stops it. Throws when it does not start (nothing left running). */
    static NetworkStateLogger start() throws Exception {
        return start(false);
    }

    /**
     * A started logger; with {@code standardViewerPort} viewers reach it on the standard viewer port (5556, what
     * {@code fdnet viewer} assumes) when that is free, else on a free one. Cores always get a free port.
     */
    static NetworkStateLogger start(boolean standardViewerPort) throws Exception {
        LoggerConfig config = LoggerConfigFile.load(LoggerConfigFile.defaultPath());
        String standard = LoggerSetting.SENDER_PORT.defaultValue();
        boolean useStandard = standardViewerPort && isFree(config.senderAddress(), Integer.parseInt(standard));
        config.set(LoggerSetting.RECEIVER_PORT, "0").set(LoggerSetting.SENDER_PORT, useStandard ? standard : "0");
        NetworkStateLogger logger = new NetworkStateLogger(config);
        try {
            logger.start();
        } catch (Exception e) {
            logger.close();
            throw e;
        }
        return logger;
    }

    /** {@code HOST:PORT} where viewers reach {@code logger} ({@code fdnet viewer --logger}). */
    static String viewerAddress(NetworkStateLogger logger) {
        String host = logger.config().senderAddress();
        return (host.isBlank() || host.equals("0.0.0.0") ? "127.0.0.1" : host) + ":" + logger.senderPort();
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
