package org.fdnet.logger;

/** Events per second from a growing counter, between two successive calls. */
final class Throughput {
    private long lastCount = -1;
    private long lastNanos;
    private double rate;

    synchronized double rate(long count) {
        long now = System.nanoTime();
        if (lastCount >= 0 && now - lastNanos > 200_000_000L) {
            rate = (count - lastCount) * 1e9 / (now - lastNanos);
            lastCount = count;
            lastNanos = now;
        } else if (lastCount < 0) {
            lastCount = count;
            lastNanos = now;
        }
        return rate;
    }
}
