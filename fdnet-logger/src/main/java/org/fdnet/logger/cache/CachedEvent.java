package org.fdnet.logger.cache;

import org.fdnet.event.NetworkEvent;

/**
 * An event in the logger's cache: the event (with its global source id), the run and sequence number it
 * came with (so commits can be acknowledged per run), its counted size, and the two facts that decide when
 * it may leave memory: {@link #committed()} and whether monitors still wait for it. Those two fields are
 * guarded by the cache's lock.
 */
public final class CachedEvent {
    private final NetworkEvent event;
    private final RunProgress run;
    private final long seq;
    private final int bytes;
    private final long arrivalNanos;
    private boolean committed;
    private boolean left;
    int pendingMonitors;

    public CachedEvent(NetworkEvent event, RunProgress run, long seq, int bytes, long arrivalNanos) {
        this.event = event;
        this.run = run;
        this.seq = seq;
        this.bytes = bytes;
        this.arrivalNanos = arrivalNanos;
    }

    public NetworkEvent event() {
        return event;
    }

    public int sourceId() {
        return event.sourceId();
    }

    public long time() {
        return event.time();
    }

    public RunProgress run() {
        return run;
    }

    public long seq() {
        return seq;
    }

    public int bytes() {
        return bytes;
    }

    public long arrivalNanos() {
        return arrivalNanos;
    }

    boolean committed() {
        return committed;
    }

    void markCommitted() {
        committed = true;
    }

    /** Evicted from its node's timeline (guarded by the cache's lock, like {@link #committed()}). */
    boolean left() {
        return left;
    }

    void markLeft() {
        left = true;
    }

    boolean evictable() {
        return committed && pendingMonitors == 0;
    }
}
