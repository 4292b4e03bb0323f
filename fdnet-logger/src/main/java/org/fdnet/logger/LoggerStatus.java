package org.fdnet.logger;

import java.util.List;
import org.fdnet.logger.cache.CacheStatus;
import org.fdnet.logger.server.ClientInfo;

/**
 * What the logger is doing (the thesis's real-time information): the cache, events per second in and
 * out, the database's state and lag, the writer's last batch (it grows with the backlog up to its maximum),
 * its connections to the database, and the connected cores and viewers with their states.
 */
public record LoggerStatus(boolean running, CacheStatus cache, double eventsInPerSecond, double eventsOutPerSecond,
                           String database, List<ClientInfo> cores, List<ClientInfo> viewers, int batchRows,
                           int maxBatchRows, int writerConnections) {

    /** The headless mode's status line. */
    public String line() {
        if (!running || cache == null) {
            return "logger stopped";
        }
        return String.format("cache %,d/%,d KiB (%.0f%%)%s | in %,.0f ev/s | out %,.0f ev/s | unwritten %,d, lag %d ms"
                        + " | batch %,d (max %,d), %d writer connection%s | db %s | cores %d | viewers %d",
                cache.usedBytes() >> 10, cache.capacityBytes() >> 10, cache.usedPercent(),
                cache.pressured() ? " PRESSURED" : "", eventsInPerSecond, eventsOutPerSecond, cache.unwritten(),
                cache.lagMillis(), batchRows, maxBatchRows, writerConnections, writerConnections == 1 ? "" : "s", database,
                active(cores), active(viewers));
    }

    private static long active(List<ClientInfo> clients) {
        return clients.stream().filter(c -> c.state() != org.fdnet.logger.server.ConnectionState.STOPPED).count();
    }
}
