package org.fdnet.logger.export;

import java.sql.Array;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fdnet.event.ValueType;
import org.fdnet.logger.store.SourceDirectory;

/**
 * Finds a recorded run in the logger's database as {@code fdnet viewer} names it: by its id (the first stream of
 * the network run, {@code (run 7)} in the viewer's list; any of its streams' ids finds it) or {@code latest}. A
 * network run over several hosts is one run: every host's stream, with its host name and clock offset.
 */
public final class StoredRuns {
    private final Connection connection;

    public StoredRuns(Connection connection) {
        this.connection = connection;
    }

    /** The run named {@code spec} ({@code latest} or a run id); an unknown one is refused with a message naming it. */
    public RecordedRun load(String spec) throws SQLException {
        int id;
        if (spec.equalsIgnoreCase("latest") || spec.equalsIgnoreCase("last")) {
            id = single("SELECT coalesce(max(run_id), 0) FROM fdnet_run");
            if (id == 0) {
                throw new IllegalArgumentException("the database holds no run yet");
            }
        } else {
            try {
                id = Integer.parseInt(spec.trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("run '" + spec + "' is not a run id (the number fdnet viewer lists"
                        + " as \"(run N)\") nor 'latest'");
            }
        }
        return load(id);
    }

    public RecordedRun load(int streamId) throws SQLException {
        int networkRunId;
        try (PreparedStatement ps = connection.prepareStatement(
                "SELECT coalesce(network_run_id, 0) FROM fdnet_run WHERE run_id = ?")) {
            ps.setInt(1, streamId);
            try (ResultSet rs = ps.executeQuery()) {
                if (!rs.next()) {
                    throw new IllegalArgumentException("run " + streamId + " is not in the database");
                }
                networkRunId = rs.getInt(1);
            }
        }
        String where = networkRunId == 0 ? "r.run_id = " + streamId : "r.network_run_id = " + networkRunId;
        Map<Integer, String> hostOfStream = new LinkedHashMap<>();
        Map<Integer, Long> offsetOfStream = new HashMap<>();
        String network = null;
        String uuid = null;
        long started = 0;
        List<String> hosts = new ArrayList<>();
        String definition = null;
        String sha = null;
        try (Statement s = connection.createStatement(); ResultSet rs = s.executeQuery(
                "SELECT r.run_id, coalesce(r.host, r.core_name), r.clock_offset, coalesce(n.network, r.core_name),"
                        + " coalesce(n.run_uuid, r.run_uuid)::text,"
                        + " coalesce(n.started, (extract(epoch FROM r.first_seen) * 1000000)::bigint), n.hosts,"
                        + " n.definition, n.definition_sha256"
                        + " FROM fdnet_run r LEFT JOIN fdnet_network_run n USING (network_run_id) WHERE " + where
                        + " ORDER BY r.run_id")) {
            while (rs.next()) {
                hostOfStream.put(rs.getInt(1), rs.getString(2));
                offsetOfStream.put(rs.getInt(1), rs.getLong(3));
                if (network == null) {
                    network = rs.getString(4);
                    uuid = rs.getString(5);
                    started = rs.getLong(6);
                    Array h = rs.getArray(7);
                    hosts.addAll(h == null ? List.of(rs.getString(2)) : Arrays.asList((String[]) h.getArray()));
                    definition = rs.getString(8);
                    sha = rs.getString(9);
                }
            }
        }
        Map<Integer, RecordedNode> nodes = new LinkedHashMap<>();
        try (Statement s = connection.createStatement(); ResultSet rs = s.executeQuery(
                "SELECT sourceid, run_id, kind, module, node FROM fdnet_node WHERE node IS NOT NULL AND run_id IN ("
                        + join(hostOfStream.keySet()) + ") ORDER BY module, node, sourceid")) {
            while (rs.next()) {
                int stream = rs.getInt(2);
                nodes.put(rs.getInt(1), new RecordedNode(rs.getInt(1), SourceDirectory.kindOf(rs.getString(3)),
                        rs.getString(4), rs.getString(5), hostOfStream.get(stream), offsetOfStream.get(stream)));
            }
        }
        int listedId = hostOfStream.keySet().iterator().next();
        return new RecordedRun(listedId, network, uuid, started, hosts, definition, sha,
                new ArrayList<>(hostOfStream.keySet()), nodes);
    }

    /**
     * The value type of each Data of {@code run} that has a value (one index lookup per node): what the wide table's
     * columns are made from before its first row.
     */
    public Map<Integer, ValueType> dataTypes(RecordedRun run) throws SQLException {
        Map<Integer, ValueType> types = new LinkedHashMap<>();
        if (run.nodes().isEmpty()) {
            return types;
        }
        try (Statement s = connection.createStatement(); ResultSet rs = s.executeQuery(
                "SELECT n.sourceid, (SELECT d.typevalue FROM datavalue_log d WHERE d.sourceid = n.sourceid LIMIT 1)"
                        + " FROM unnest(ARRAY[" + join(run.nodes().keySet()) + "]) AS n(sourceid)")) {
            while (rs.next()) {
                int code = rs.getInt(2);
                if (!rs.wasNull()) {
                    types.put(rs.getInt(1), ValueType.fromCode(code));
                }
            }
        }
        return types;
    }

    /** The common-clock times (µs) of the run's first and last value, Datas' and Relations'; {0, 0} when it has none. */
    public long[] timeSpan(RecordedRun run) throws SQLException {
        String streams = join(run.streams());
        String sql = "SELECT min(t), max(t) FROM (SELECT d.time - r.clock_offset AS t FROM datavalue_log d"
                + " JOIN fdnet_node n ON n.sourceid = d.sourceid JOIN fdnet_run r ON r.run_id = n.run_id WHERE r.run_id IN ("
                + streams + ") UNION ALL SELECT p.time - r.clock_offset FROM procvalue_log p JOIN fdnet_node n"
                + " ON n.sourceid = p.sourceid JOIN fdnet_run r ON r.run_id = n.run_id WHERE r.run_id IN (" + streams + ")) v";
        try (Statement s = connection.createStatement(); ResultSet rs = s.executeQuery(sql)) {
            rs.next();
            return new long[] {rs.getLong(1), rs.getLong(2)};
        }
    }

    private int single(String sql) throws SQLException {
        try (Statement s = connection.createStatement(); ResultSet rs = s.executeQuery(sql)) {
            rs.next();
            return rs.getInt(1);
        }
    }

    static String join(java.util.Collection<Integer> ids) {
        StringBuilder b = new StringBuilder();
        for (int id : ids) {
            if (b.length() > 0) {
                b.append(',');
            }
            b.append(id);
        }
        return b.toString();
    }
}
