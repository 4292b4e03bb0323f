package org.fdnet.logger.writer;

import org.fdnet.logger.config.LoggerConfig;

/**
 * The writer's parameters (the thesis's "Logger writer" panel and the priority switch). {@code batchSize}
 * and {@code batchTimeoutMillis} are the thesis's latency settings; under backlog batches grow up to
 * {@code maxBatchRows} events and {@code maxBatchBytes} counted bytes (see {@link BatchSizer}), and up to
 * {@code connections} batches are in flight at once, one per connection, committed in order.
 */
public record WriterSettings(int batchSize, int maxBatchRows, long maxBatchBytes, long batchTimeoutMillis, long writingDelayMillis, boolean reconnect,
                             int reconnectAttempts, long reconnectDelayMillis, boolean priorityEnabled, int connections) {

    public static WriterSettings of(LoggerConfig c) {
        return new WriterSettings(c.batchSize(), c.maxBatchRows(), c.maxBatchBytes(), c.batchTimeoutMillis(), c.writingDelayMillis(), c.reconnect(),
                c.reconnectAttempts(), c.reconnectDelayMillis(), c.priorityEnabled(), c.writerConnections());
    }
}
