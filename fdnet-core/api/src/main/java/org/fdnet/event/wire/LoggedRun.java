package org.fdnet.event.wire;

/**
 * One stream of events the logger holds (a core's {@code fdnet_run} row) and the network run it is a part of:
 * {@code networkRunId} 0 when the core named none (the stream is a run of its own, {@code network} its core name).
 * {@code clockOffsetMicros}: how far the stream's host's clock was ahead of the run's coordinator's; a viewer
 * subtracts it to put every host on one time axis. On the wire: {@code i32 streamId, i32 networkRunId,
 * string network, string host, i64 started, u32 hostCount, i64 clockOffset}.
 */
public record LoggedRun(int streamId, int networkRunId, String network, String host, long startedMicros,
                        int hostCount, long clockOffsetMicros) {
    /** The least bytes one takes on the wire (two empty strings). */
    public static final int MIN_BYTES = 4 + 4 + 4 + 4 + 8 + 4 + 8;

    public void write(FrameWriter w) {
        w.putInt(streamId).putInt(networkRunId).putString(network).putString(host).putLong(startedMicros)
                .putInt(hostCount).putLong(clockOffsetMicros);
    }

    public static LoggedRun read(Frame f) throws ProtocolException {
        return new LoggedRun(f.getInt(), f.getInt(), f.getString(), f.getString(), f.getLong(), f.getInt(), f.getLong());
    }
}
