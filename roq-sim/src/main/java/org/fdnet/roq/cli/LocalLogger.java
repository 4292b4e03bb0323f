package org.fdnet.roq.cli;

import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerConfigFile;
import org.fdnet.logger.config.LoggerSetting;

/**
 * Starts a network state logger in this process (its embedded PostgreSQL, free ports) for a command that records
 * what it runs: {@code fdnet demo} and {@code fdnet bench roq}.
 */
final class LocalLogger {
    private LocalLogger() {
    }

    /** A started logger on free ports; the caller stops it. Throws when it does not start (nothing left running). */
    static NetworkStateLogger start() throws Exception {
        LoggerConfig config = LoggerConfigFile.load(LoggerConfigFile.defaultPath());
        config.set(LoggerSetting.RECEIVER_PORT, "0").set(LoggerSetting.SENDER_PORT, "0");
        NetworkStateLogger logger = new NetworkStateLogger(config);
        try {
            logger.start();
        } catch (Exception e) {
            logger.close();
            throw e;
        }
        return logger;
    }
}
