package org.fdnet.logger.export;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What an export knows of a run before its first row: the id it is listed by ({@code fdnet viewer}'s run id),
 * the network's name, the run's UUID and start (µs on the coordinator's clock; 0 and empty when the core named no
 * run), its hosts, the {@code .fdn} as deployed (null when the database does not hold it) and its SHA-256, and
 * its streams (one {@code fdnet_run} row per recording host) and every node the export may see, by source id.
 */
public record RecordedRun(int runId, String network, String uuid, long startedMicros, List<String> hosts,
                          String definition, String definitionSha256, List<Integer> streams,
                          Map<Integer, RecordedNode> nodes) {
    public RecordedRun {
        hosts = List.copyOf(hosts);
        streams = List.copyOf(streams);
        nodes = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(nodes));
    }

    /** The node of a source id, or a stand-in named by the id when the run never named it. */
    public RecordedNode node(int sourceId) {
        RecordedNode n = nodes.get(sourceId);
        return n != null ? n : new RecordedNode(sourceId, null, "fdnet", "source-" + sourceId, "", 0);
    }

    /** The run's identity as MCAP metadata and CSV comments: name, UUID, start, hosts, definition's hash. */
    public Map<String, String> identity() {
        Map<String, String> m = new LinkedHashMap<>();
        m.put("run_id", Integer.toString(runId));
        m.put("network", network);
        m.put("run_uuid", uuid);
        m.put("started_us", Long.toString(startedMicros));
        m.put("hosts", String.join(",", hosts));
        m.put("clock", "µs since the epoch on the run's coordinator's clock (each host's offset applied)");
        if (definitionSha256 != null) {
            m.put("definition_sha256", definitionSha256);
        }
        return m;
    }
}
