package org.fdnet.viewer.source;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.viewer.data.PlotData;

/**
 * Prepares a {@link Replay} of a recorded run: reads the history of the run's Data nodes from the logger,
 * keeps the values between {@code fromSeconds} and {@code toSeconds} after the run's first value (a
 * negative {@code fromSeconds} counts from the run's last value: {@code -60} is "the last minute"), and
 * aims the replay at {@code into} (its samples cleared, the run's nodes tracked). Not started.
 */
public final class ReplayLoader {
    private ReplayLoader() {
    }

    public static Replay load(LoggerConnection connection, RunInfo run, double fromSeconds, double toSeconds,
            double speed, PlotData into) throws IOException {
        if (!(toSeconds > fromSeconds) && fromSeconds >= 0) {
            throw new IllegalArgumentException("replay range " + fromSeconds + " s .. " + toSeconds
                    + " s: 'to' must be after 'from'");
        }
        List<NetworkEvent> all = connection.history(run.sourceIds(), 0, Long.MAX_VALUE);
        List<NetworkEvent> values = new ArrayList<>(all.size());
        for (NetworkEvent e : all) {
            if (e instanceof DataValueEvent) {
                values.add(e);
            }
        }
        if (values.isEmpty()) {
            throw new IllegalArgumentException(run + " has no recorded values");
        }
        long first = values.get(0).time();
        long last = values.get(values.size() - 1).time();
        long from;
        long to;
        if (fromSeconds < 0) {
            from = last + (long) (fromSeconds * 1e6);
            to = last;
        } else {
            from = first + (long) (fromSeconds * 1e6);
            to = first + (long) (toSeconds * 1e6);
        }
        List<NetworkEvent> range = new ArrayList<>();
        for (NetworkEvent e : values) {
            if (e.time() >= from && e.time() <= to) {
                range.add(e);
            }
        }
        into.clearSamples();
        for (LoggedNode n : run.nodes()) {
            into.track(n.sourceId(), LoggerConnection.label(n), "");
        }
        return new Replay(range, speed, into::accept);
    }
}
