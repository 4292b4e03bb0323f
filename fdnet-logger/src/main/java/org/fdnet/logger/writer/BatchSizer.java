package org.fdnet.logger.writer;

/**
 * How many events the writer's next batch takes. At low load it is the thesis's batch size (with the timer,
 * the latency settings). When events wait behind the batch being written, the next one grows with that
 * backlog — at most doubling from one batch to the next, up to {@code maxRows} — so the per-commit costs
 * (the COPY's start, the watermark UPDATE, the COMMIT and its WAL flush) are spread over more rows exactly
 * when the writer is behind; as soon as the backlog falls, the batch falls with it, down to the base size.
 * The cap in bytes is applied when the batch is taken ({@code EventCache.takeBatch}).
 */
final class BatchSizer {
    private final int baseRows;
    private final int maxRows;
    private int current;

    BatchSizer(int baseRows, int maxRows) {
        this.baseRows = baseRows;
        this.maxRows = Math.max(baseRows, maxRows);
        this.current = baseRows;
    }

    /** The size of the next batch when {@code backlog} events are waiting to be written. */
    int next(int backlog) {
        int grown = (int) Math.min(maxRows, Math.max((long) baseRows, 2L * current));
        current = Math.max(baseRows, Math.min(backlog, grown));
        return current;
    }

    /** The size of the last batch decided (the base size before the first one). */
    int current() {
        return current;
    }

    int maxRows() {
        return maxRows;
    }
}
