package org.fdnet.logger.cache;

/**
 * A snapshot of the cache: bytes used of the capacity, events held (of which not yet written and still
 * monitored), events received and committed since start, whether the receiver is held back, and the age of
 * the oldest unwritten event (the database lag).
 */
public record CacheStatus(long usedBytes, long capacityBytes, long events, long unwritten, long monitored,
                          long received, long committed, boolean pressured, long lagMillis, int monitors) {
    public long freeBytes() {
        return Math.max(0, capacityBytes - usedBytes);
    }

    public double usedPercent() {
        return 100.0 * usedBytes / capacityBytes;
    }
}
