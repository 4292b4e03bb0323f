package org.fdnet.event.wire;

import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import org.fdnet.event.RunIdentity;

/**
 * The {@code RUN} frame: which network run a core's events belong to, which host of it the core is, and how
 * far that host's clock is ahead of the run's coordinator's (µs, measured by the coordinator). A core
 * that knows its run sends it right after WELCOME, on every connection, before any EVENTS; the logger records
 * it idempotently, so a resend after a reconnect changes nothing.
 *
 * @param run               the network run
 * @param host              the host this core is
 * @param clockOffsetMicros how far this host's clock is ahead of the coordinator's, µs (negative: behind)
 */
public record RunFrame(RunIdentity run, String host, long clockOffsetMicros) {
    /** At most this many hosts in one run (a malformed frame cannot make the logger allocate more). */
    public static final int MAX_HOSTS = 4096;

    /**
     * Appends this frame to {@code w}.
     *
     * @param w the writer to add the frame to
     */
    public void write(FrameWriter w) {
        w.begin(MessageType.RUN).putLong(run.id().getMostSignificantBits()).putLong(run.id().getLeastSignificantBits())
                .putString(run.network()).putString(host).putLong(clockOffsetMicros).putLong(run.startedMicros()).putString(run.sha256())
                .putInt(run.hosts().size());
        run.hosts().forEach(w::putString);
        w.putString(run.definition());
    }

    /**
     * Reads a RUN frame's payload.
     *
     * @param f a frame of type RUN, its cursor at the payload's start
     * @return the run, host and clock offset
     * @throws ProtocolException when the payload is malformed, names more than {@link #MAX_HOSTS} hosts, or has
     *                           trailing bytes
     */
    public static RunFrame read(Frame f) throws ProtocolException {
        UUID id = new UUID(f.getLong(), f.getLong());
        String network = f.getString();
        String host = f.getString();
        long offset = f.getLong();
        long started = f.getLong();
        String sha256 = f.getString();
        int n = f.getCount(4);
        if (n > MAX_HOSTS) {
            throw new ProtocolException("RUN frame names " + n + " hosts (at most " + MAX_HOSTS + ")");
        }
        List<String> hosts = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            hosts.add(f.getString());
        }
        String definition = f.getString();
        f.expectEnd();
        return new RunFrame(new RunIdentity(id, network, definition, sha256, started, hosts), host, offset);
    }
}
