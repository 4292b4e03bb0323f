package org.fdnet.logger.cache;

import java.util.UUID;
import java.util.function.LongConsumer;

/**
 * One core run as the logger tracks it: its id in the database, the highest sequence number received (to
 * drop what a reconnecting core sends again) and the highest committed (what the core is told, and may
 * forget). {@code received} is guarded by this object's monitor; {@code committed} only grows.
 */
public final class RunProgress {
    private final int runId;
    private final UUID uuid;
    private long received;
    private volatile long committed;
    private volatile LongConsumer ackListener = seq -> { };

    public RunProgress(int runId, UUID uuid, long committed) {
        this.runId = runId;
        this.uuid = uuid;
        this.committed = committed;
        this.received = committed;
    }

    public int runId() {
        return runId;
    }

    public UUID uuid() {
        return uuid;
    }

    public synchronized long received() {
        return received;
    }

    public synchronized void received(long seq) {
        received = Math.max(received, seq);
    }

    public long committed() {
        return committed;
    }

    /** Called by the writer after a commit; tells the run's connected core. */
    public void committed(long seq) {
        if (seq > committed) {
            committed = seq;
            ackListener.accept(seq);
        }
    }

    public void ackListener(LongConsumer listener) {
        ackListener = listener;
    }
}
