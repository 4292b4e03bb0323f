package org.fdnet.logger.writer;

/**
 * How many events the writer's next batch takes. At low load it is the thesis's batch size (with the timer,
 * the latency settings). When events wait behind the batch being written, the next one grows with that
 * backlog — at most doubling from one batch to the next, up to {@code maxRows} — so the per-commit costs
 * (the COPY's start, the watermark UPDATE, the COMMIT and its WAL flush) are spread over more rows exactly
 * when the writer is behind; as soon as the backlog falls, the batch falls with it, down to the base size.
 * The cap in bytes is applied when the batch is taken ({@code EventCache.takeBatch}).
 *
 * <p>With several lanes (connections) a batch takes a share of the backlog, not all of it: the events the
 * writer holds — waiting in the cache plus in flight on the lanes — divided by {@code lanes + 1}, so that
 * under a closed loop (clients whose window of unacknowledged events is bounded) every lane has a batch and
 * one more is ready when a lane frees (Little's law: the events circulating are what keeps the lanes busy;
 * a batch that takes the whole backlog leaves a freed lane idle until the ACK → client → TCP → receiver
 * cycle refills the cache). The share never goes below {@link #pipelineFloor()} (10,000 events, or the
 * base / maximum size when those bound it) so commits stay amortised.
 */
final class BatchSizer {
    /** The smallest share of the backlog a pipelined batch is cut to (commits stay a small part of its cost). */
    static final int PIPELINE_FLOOR_ROWS = 10_000;

    private final int baseRows;
    private final int maxRows;
    private final int lanes;
    private final int pipelineFloor;
    private int current;

    BatchSizer(int baseRows, int maxRows) {
        this(baseRows, maxRows, 1);
    }

    BatchSizer(int baseRows, int maxRows, int lanes) {
        this.baseRows = baseRows;
        this.maxRows = Math.max(baseRows, maxRows);
        this.lanes = Math.max(1, lanes);
        this.pipelineFloor = Math.max(baseRows, Math.min(this.maxRows, PIPELINE_FLOOR_ROWS));
        this.current = baseRows;
    }

    /** The size of the next batch when {@code backlog} events are waiting and none is in flight. */
    int next(int backlog) {
        return next(backlog, 0);
    }

    /**
     * The size of the next batch when {@code waiting} events wait in the cache and {@code inFlight} events
     * are being written on the other lanes.
     */
    int next(int waiting, int inFlight) {
        int grown = (int) Math.min(maxRows, Math.max((long) baseRows, 2L * current));
        int wanted = grown;
        if (lanes > 1) {
            long share = ((long) waiting + inFlight) / (lanes + 1);
            wanted = (int) Math.min(grown, Math.max(pipelineFloor, share));
        }
        current = Math.max(baseRows, Math.min(waiting, wanted));
        return current;
    }

    /**
     * With several lanes, the fewest ready events worth a batch on a free lane while others are in flight
     * (fewer: the writer waits for more or for the batch in flight); with one lane, the base size.
     */
    int pipelineFloor() {
        return lanes > 1 ? pipelineFloor : baseRows;
    }

    /** The size of the last batch decided (the base size before the first one). */
    int current() {
        return current;
    }

    int maxRows() {
        return maxRows;
    }
}
