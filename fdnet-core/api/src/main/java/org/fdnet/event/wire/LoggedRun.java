package org.fdnet.event.wire;

/**
 * One stream of events the logger holds (a core's {@code fdnet_run} row) and the network run it is a part of:
 * {@code networkRunId} 0 when the core named none (the stream is a run of its own, {@code network} its core name).
 * {@code clockOffsetMicros}: how far the stream's host's clock was ahead of the run's coordinator's; a viewer
 * subtracts it to put every host on one time axis. On the wire: {@code i32 streamId, i32 networkRunId,
 * string network, string host, i64 started, u32 hostCount, i64 clockOffset}.
 *
 * @param streamId          the logger's id of the stream
 * @param networkRunId      the network run it is part of, 0 for none
 * @param network           the network's name, or the core's name when it named no run
 * @param host              the host the stream came from
 * @param startedMicros     when the run started, µs since the epoch
 * @param hostCount         how many hosts the network run spans
 * @param clockOffsetMicros how far the host's clock was ahead of the coordinator's, µs
 */
public record LoggedRun(int streamId, int networkRunId, String network, String host, long startedMicros,
                        int hostCount, long clockOffsetMicros) {
    /** The least bytes one takes on the wire (two empty strings). */
    public static final int MIN_BYTES = 4 + 4 + 4 + 4 + 8 + 4 + 8;

    /**
     * Appends this stream to the frame {@code w} is building.
     *
     * @param w a writer inside a frame
     */
    public void write(FrameWriter w) {
        w.putInt(streamId).putInt(networkRunId).putString(network).putString(host).putLong(startedMicros)
                .putInt(hostCount).putLong(clockOffsetMicros);
    }

    /**
     * Reads one stream at the frame's cursor.
     *
     * @param f a frame positioned on a stream
     * @return the stream; the cursor is after it
     * @throws ProtocolException when the payload ends inside it
     */
    public static LoggedRun read(Frame f) throws ProtocolException {
        return new LoggedRun(f.getInt(), f.getInt(), f.getString(), f.getString(), f.getLong(), f.getInt(), f.getLong());
    }
}
