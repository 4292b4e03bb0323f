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
    /** The event as a plotting viewer receives it, encoded the first time one asks (see {@link #wire()}). */
    private volatile byte[] wire;

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

    /**
     * The event's encoding for a plot's history ({@code EventCodec.writeNumeric}) if a sender kept it, else
     * {@code null}. Kept only for events a viewer asked for: an array of 21 bytes for a number (16 more of
     * array header, 40 in all), once per event; then every later answer is an array copy, not an encoding.
     */
    public byte[] wire() {
        return wire;
    }

    /** Keeps the event's wire encoding (two senders may race: both encode the same bytes). */
    public void keepWire(byte[] encoded) {
        wire = encoded;
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
