package org.fdnet.logger.export;

import java.nio.charset.StandardCharsets;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.Base64;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.UUID;
import org.fdnet.event.ValueType;
import org.fdnet.logger.store.Schema;

/**
 * A random recorded run written straight into the logger's tables: hosts with clock offsets, Datas of every value
 * type (awkward values too: NaN, infinities, quotes, tabs, backslashes, Japanese text, empty vectors), Relation
 * values and structure changes, inserted in shuffled order (arrival out of time order). Answers the run's id.
 */
final class SyntheticRun {
    private static final String[] MODULES = {"main", "Balance", "歩行", "Walk/Gait"};
    private static final String[] NAMES = {"Joint1", "posture", "足の力", "stability margin", "地図, \"北\"", "x\ty"};

    private SyntheticRun() {
    }

    record Row(int kind, int sourceId, long time, ValueType type, String value, String[] command) {
    }

    static int write(Connection c, long seed, int events, int hosts) throws SQLException {
        Schema.create(c);
        Random rnd = new Random(seed);
        String uuid = UUID.nameUUIDFromBytes(("run" + seed + "/" + events).getBytes(StandardCharsets.UTF_8)).toString();
        long started = 1_795_000_000_000_000L + rnd.nextInt(1_000_000_000);
        List<String> hostNames = new ArrayList<>();
        for (int h = 0; h < hosts; h++) {
            hostNames.add(h == 0 ? "robot" : "host-" + h);
        }
        int networkRun;
        try (PreparedStatement ps = c.prepareStatement("INSERT INTO fdnet_network_run (run_uuid, network, definition,"
                + " definition_sha256, started, hosts) VALUES (?::uuid, ?, ?, ?, ?, ?) RETURNING network_run_id")) {
            ps.setString(1, uuid);
            ps.setString(2, "synthetic-" + seed);
            ps.setString(3, "<?xml version=\"1.0\"?><cnet name=\"synthetic\"/>");
            ps.setString(4, "00");
            ps.setLong(5, started);
            ps.setArray(6, c.createArrayOf("text", hostNames.toArray()));
            networkRun = single(ps);
        }
        int firstStream = 0;
        List<Integer> sources = new ArrayList<>();
        List<ValueType> types = new ArrayList<>();
        int nextSource = 1 + (int) seed * 100;
        for (int h = 0; h < hosts; h++) {
            int stream;
            try (PreparedStatement ps = c.prepareStatement("INSERT INTO fdnet_run (run_uuid, core_name, network_run_id,"
                    + " host, clock_offset) VALUES (?::uuid, ?, ?, ?, ?) RETURNING run_id")) {
                ps.setString(1, UUID.nameUUIDFromBytes((uuid + h).getBytes(StandardCharsets.UTF_8)).toString());
                ps.setString(2, hostNames.get(h));
                ps.setInt(3, networkRun);
                ps.setString(4, hostNames.get(h));
                ps.setLong(5, h == 0 ? 0 : (h % 2 == 0 ? -2_000_000L : 5_000_000L)); // 5 s ahead, 2 s behind
                stream = single(ps);
            }
            if (h == 0) {
                firstStream = stream;
            }
            try (PreparedStatement ps = c.prepareStatement("INSERT INTO fdnet_node (sourceid, run_id, local_id, kind,"
                    + " module, node, named_at) VALUES (?, ?, ?, ?, ?, ?, 0)")) {
                for (int local = 0; local < 8; local++) {
                    int id = nextSource++;
                    boolean relation = local == 7;
                    ps.setInt(1, id);
                    ps.setInt(2, stream);
                    ps.setInt(3, local);
                    ps.setString(4, relation ? "proc" : "data");
                    ps.setString(5, MODULES[local % MODULES.length]);
                    ps.setString(6, NAMES[local % NAMES.length] + (local >= NAMES.length ? " " + local : ""));
                    ps.addBatch();
                    sources.add(id);
                    types.add(relation ? null : ValueType.values()[local % ValueType.values().length]);
                }
                ps.executeBatch();
            }
        }
        List<Row> rows = new ArrayList<>();
        long[] lastTime = new long[sources.size()];
        for (int i = 0; i < events; i++) {
            int k = rnd.nextInt(sources.size() + 1);
            long time = started + (long) i * 137 + rnd.nextInt(100);
            if (k == sources.size()) {
                rows.add(new Row(3, sources.get(0), time, null, null, new String[] {rnd.nextBoolean() ? "controller" : "proc",
                        rnd.nextBoolean() ? "load" : "unload", MODULES[rnd.nextInt(MODULES.length)], "module"}));
                continue;
            }
            if (time <= lastTime[k]) {
                time = lastTime[k] + 1; // (sourceid, time) is the tables' key
            }
            lastTime[k] = time;
            ValueType t = types.get(k);
            rows.add(new Row(t == null ? 2 : 1, sources.get(k), time, t, t == null ? text(rnd) : value(t, rnd), null));
        }
        Collections.shuffle(rows, rnd);
        try (PreparedStatement d = c.prepareStatement("INSERT INTO datavalue_log (sourceid, time, value, typevalue) VALUES (?, ?, ?, ?)");
             PreparedStatement p = c.prepareStatement("INSERT INTO procvalue_log (sourceid, time, value) VALUES (?, ?, ?)");
             PreparedStatement n = c.prepareStatement("INSERT INTO netcommand_log (sourceid, sourcetype, command, params_id,"
                     + " params_type, time) VALUES (?, ?, ?, ?, ?, ?)")) {
            for (Row r : rows) {
                switch (r.kind) {
                    case 1 -> {
                        d.setInt(1, r.sourceId);
                        d.setLong(2, r.time);
                        d.setString(3, r.value);
                        d.setInt(4, r.type.code());
                        d.addBatch();
                    }
                    case 2 -> {
                        p.setInt(1, r.sourceId);
                        p.setLong(2, r.time);
                        p.setString(3, r.value);
                        p.addBatch();
                    }
                    default -> {
                        n.setInt(1, r.sourceId);
                        n.setString(2, r.command[0]);
                        n.setString(3, r.command[1]);
                        n.setString(4, r.command[2]);
                        n.setString(5, r.command[3]);
                        n.setLong(6, r.time);
                        n.addBatch();
                    }
                }
            }
            d.executeBatch();
            p.executeBatch();
            n.executeBatch();
        }
        return firstStream;
    }

    private static String value(ValueType t, Random rnd) {
        return switch (t) {
            case BOOLEAN -> Boolean.toString(rnd.nextBoolean());
            case LONG -> Long.toString(rnd.nextInt(4) == 0 ? rnd.nextLong() : rnd.nextInt(2000) - 1000);
            case DOUBLE -> Double.toString(awkwardDouble(rnd));
            case STRING -> text(rnd);
            case BYTES -> {
                byte[] b = new byte[rnd.nextInt(12)];
                rnd.nextBytes(b);
                yield Base64.getEncoder().encodeToString(b);
            }
            case DOUBLES -> {
                StringBuilder s = new StringBuilder();
                int n = rnd.nextInt(5);
                for (int i = 0; i < n; i++) {
                    s.append(i > 0 ? "," : "").append(awkwardDouble(rnd));
                }
                yield s.toString();
            }
        };
    }

    private static double awkwardDouble(Random rnd) {
        return switch (rnd.nextInt(12)) {
            case 0 -> Double.NaN;
            case 1 -> rnd.nextBoolean() ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
            case 2 -> rnd.nextDouble() * 1e-9;
            case 3 -> rnd.nextGaussian() * 1e12;
            case 4 -> -0.0;
            default -> rnd.nextGaussian();
        };
    }

    private static String text(Random rnd) {
        String[] parts = {"ok", "歩く", "a\tb", "line\nbreak", "back\\slash", "\"quoted\"", "", "comma, here", "\u0001"};
        return parts[rnd.nextInt(parts.length)] + (rnd.nextBoolean() ? "" : parts[rnd.nextInt(parts.length)]);
    }

    private static int single(PreparedStatement ps) throws SQLException {
        try (ResultSet rs = ps.executeQuery()) {
            rs.next();
            return rs.getInt(1);
        }
    }

    /**
     * The run's rows as PostgreSQL itself renders them (json_build_object), one JSON object a line: what the readers
     * must find in the file, written without the exporter's code.
     */
    static long expectedRows(Connection c, int stream, java.nio.file.Path out) throws SQLException, java.io.IOException {
        String runs = "(SELECT run_id FROM fdnet_run WHERE network_run_id = (SELECT network_run_id FROM fdnet_run WHERE run_id = "
                + stream + "))";
        String sql = "SELECT json_build_object('topic', '/' || n.module || '/' || n.node, 'log_time', ((d.time - r.clock_offset) * 1000)::text,"
                + " 'kind', 'data', 'type', d.typevalue, 'value', d.value)::text FROM datavalue_log d JOIN fdnet_node n"
                + " ON n.sourceid = d.sourceid JOIN fdnet_run r ON r.run_id = n.run_id WHERE r.run_id IN " + runs
                + " UNION ALL SELECT json_build_object('topic', '/' || n.module || '/' || n.node, 'log_time',"
                + " ((p.time - r.clock_offset) * 1000)::text, 'kind', 'relation', 'value', p.value)::text FROM procvalue_log p"
                + " JOIN fdnet_node n ON n.sourceid = p.sourceid JOIN fdnet_run r ON r.run_id = n.run_id WHERE r.run_id IN " + runs
                + " UNION ALL SELECT json_build_object('topic', '/fdnet/structure', 'log_time', ((x.time - r.clock_offset) * 1000)::text,"
                + " 'kind', 'command', 'command', x.command, 'source_type', x.sourcetype, 'params_id', x.params_id,"
                + " 'params_type', x.params_type)::text FROM netcommand_log x JOIN fdnet_node n ON n.sourceid = x.sourceid"
                + " JOIN fdnet_run r ON r.run_id = n.run_id WHERE r.run_id IN " + runs;
        long count = 0;
        try (Statement s = c.createStatement(); ResultSet rs = s.executeQuery(sql);
             java.io.BufferedWriter w = java.nio.file.Files.newBufferedWriter(out, StandardCharsets.UTF_8)) {
            while (rs.next()) {
                w.write(rs.getString(1));
                w.write('\n');
                count++;
            }
        }
        return count;
    }
}
