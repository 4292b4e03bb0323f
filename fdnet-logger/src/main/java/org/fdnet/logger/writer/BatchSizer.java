package org.fdnet.logger.writer;

/**
 * How many events the writer's next batch takes. At low load it is the thesis's batch size (with the timer,
 * the latency settings). When events wait behind the batch being written, the next one grows with that
 * backlog — at most doubling from one batch to the next, up to {@code maxRows} — so the per-commit costs
 * (the COPY's start, the watermark UPDATE, the COMMIT and its WAL flush) are spread over more rows exactly
 * when the writer is behind; as soon as the backlog falls, the batch falls with it, down to the base size.
 * The cap in bytes is applied when the batch is taken ({@code EventCache.takeBatch}).
 *
 * <p>With several lanes (connections) the writer hands a free lane its next batch as soon as
 * {@link #pipelineFloor()} events are ready (10,000, or the base / maximum size when those bound it) — not a
 * batch of the base size, which would hold the lane for a few rows until the batch before it commits, and
 * not only after every lane is done. The batch then takes what is ready (growing as above): under a closed
 * loop (clients whose window of unacknowledged events is bounded) the batch sizes follow what arrives while
 * the lanes write, and no lane waits for the ACK → client → TCP → receiver cycle while enough is ready.
 */
final class BatchSizer {
    /** The fewest ready events worth a batch on a free lane while another is in flight (commits stay amortised). */
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

    /** The size of the next batch when {@code backlog} events are waiting to be written. */
    int next(int backlog) {
        return next(backlog, false);
    }

    /**
     * As {@link #next(int)}; {@code besideAnother}: the batch goes to a free lane while another is in flight,
     * so it takes at least {@link #pipelineFloor()} of the backlog, however small the last batch was.
     */
    int next(int backlog, boolean besideAnother) {
        int grown = (int) Math.min(maxRows, Math.max((long) baseRows, 2L * current));
        if (besideAnother) {
            grown = Math.max(grown, pipelineFloor());
        }
        current = Math.max(baseRows, Math.min(backlog, grown));
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
