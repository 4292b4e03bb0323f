package org.fdnet.viewer.source;

import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import org.fdnet.event.wire.LoggedNode;

/**
 * A run the logger recorded, with every host's Data nodes: the streams of one network run (one per host), or one
 * stream of its own (a core that named no run). {@code runId} is its first stream's id (what {@code --replay}
 * takes); {@code hostOfStream} names the host of each stream, so nodes can be shown by host.
 */
public record RunInfo(int runId, String network, int hostCount, long startedMicros, List<LoggedNode> nodes,
                      Map<Integer, String> hostOfStream) {
    private static final DateTimeFormatter STARTED = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss")
            .withZone(ZoneId.systemDefault());

    /** A run whose streams the logger did not describe (an older logger): named by its id. */
    public static RunInfo ofStream(int streamId, List<LoggedNode> nodes) {
        return new RunInfo(streamId, "", 1, 0, nodes, Map.of());
    }

    public int[] sourceIds() {
        return nodes.stream().mapToInt(LoggedNode::sourceId).toArray();
    }

    /** The host a node of this run was recorded on ({@code ""} when not known). */
    public String hostOf(LoggedNode node) {
        return hostOfStream.getOrDefault(node.runId(), "");
    }

    /** The run's Datas grouped by host (hosts in name order), then by name. */
    public List<LoggedNode> nodesByHost() {
        return nodes.stream().sorted(Comparator.comparing(this::hostOf).thenComparing(LoggerConnection::label)).toList();
    }

    @Override
    public String toString() {
        if (network.isEmpty()) {
            return "run " + runId + " (" + nodes.size() + " Datas)";
        }
        return network + ", " + hostCount + (hostCount == 1 ? " host" : " hosts") + ", started "
                + STARTED.format(Instant.ofEpochMilli(startedMicros / 1000)) + " (run " + runId + ")";
    }
}
