package org.fdnet.logger.cache;

/**
 * The cache's sizes (thesis, chapter 4 VII C): its capacity in bytes, the bytes counted per state and
 * per command event (plus the value's characters), and the critical and normal levels in percent.
 */
public record CacheLimits(long capacityBytes, int networkEventBytes, int commandEventBytes, int criticalPercent,
                          int normalPercent) {
    public CacheLimits {
        if (capacityBytes < 1) {
            throw new IllegalArgumentException("capacityBytes must be at least 1, was " + capacityBytes);
        }
        if (normalPercent >= criticalPercent) {
            throw new IllegalArgumentException("normalPercent must be below criticalPercent (" + criticalPercent
                    + "), was " + normalPercent);
        }
    }

    long criticalBytes() {
        return capacityBytes / 100 * criticalPercent;
    }

    long normalBytes() {
        return capacityBytes / 100 * normalPercent;
    }
}
