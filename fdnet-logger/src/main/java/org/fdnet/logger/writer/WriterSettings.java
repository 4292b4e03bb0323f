package org.fdnet.logger.writer;

import org.fdnet.logger.config.LoggerConfig;

/** The writer's parameters (the thesis's "Logger writer" panel and the priority switch). */
public record WriterSettings(int batchSize, long batchTimeoutMillis, long writingDelayMillis, boolean reconnect,
                             int reconnectAttempts, long reconnectDelayMillis, boolean priorityEnabled) {

    public static WriterSettings of(LoggerConfig c) {
        return new WriterSettings(c.batchSize(), c.batchTimeoutMillis(), c.writingDelayMillis(), c.reconnect(),
                c.reconnectAttempts(), c.reconnectDelayMillis(), c.priorityEnabled());
    }
}
