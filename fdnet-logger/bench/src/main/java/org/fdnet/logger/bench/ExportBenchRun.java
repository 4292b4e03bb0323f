package org.fdnet.logger.bench;

import java.nio.charset.StandardCharsets;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.Random;
import java.util.UUID;
import org.fdnet.logger.store.Schema;
import org.postgresql.PGConnection;
import org.postgresql.copy.CopyIn;

/**
 * A recorded run for the export benchmark, written straight into the logger's tables: one host, {@code nodes} Datas
 * like a RoQ network's (two thirds numbers, a quarter 12-element vectors such as joint angles, the rest integers), a
 * value of each in turn every 100 µs, {@code events} rows in all. Answers the run's id.
 */
final class ExportBenchRun {
    private ExportBenchRun() {
    }

    static int fill(Connection c, long events, int nodes) throws SQLException {
        Schema.create(c);
        int stream;
        try (Statement s = c.createStatement()) {
            String uuid = UUID.randomUUID().toString();
            s.execute("INSERT INTO fdnet_network_run (run_uuid, network, definition, definition_sha256, started, hosts)"
                    + " VALUES ('" + uuid + "', 'bench-export', '<cnet name=\"bench-export\"/>', '00', 1795000000000000,"
                    + " ARRAY['bench'])");
            try (ResultSet rs = s.executeQuery("INSERT INTO fdnet_run (run_uuid, core_name, network_run_id, host)"
                    + " SELECT '" + UUID.randomUUID() + "', 'bench', network_run_id, 'bench' FROM fdnet_network_run"
                    + " WHERE run_uuid = '" + uuid + "' RETURNING run_id")) {
                rs.next();
                stream = rs.getInt(1);
            }
            int first;
            try (ResultSet rs = s.executeQuery("SELECT nextval('fdnet_sourceid_block')")) {
                rs.next();
                first = rs.getInt(1);
            }
            StringBuilder names = new StringBuilder("INSERT INTO fdnet_node (sourceid, run_id, local_id, kind, module, node) VALUES ");
            for (int n = 0; n < nodes; n++) {
                names.append(n > 0 ? "," : "").append('(').append(first + n).append(',').append(stream).append(',')
                        .append(n).append(",'data','bench','node ").append(n).append("')");
            }
            s.execute(names.toString());
            copyValues(c, first, events, nodes);
            s.execute("ANALYZE datavalue_log");
        }
        return stream;
    }

    private static void copyValues(Connection c, int firstSource, long events, int nodes) throws SQLException {
        Random rnd = new Random(1);
        CopyIn in = c.unwrap(PGConnection.class).getCopyAPI().copyIn(
                "COPY datavalue_log (sourceid, time, value, typevalue) FROM STDIN");
        try {
            StringBuilder rows = new StringBuilder(1 << 20);
            for (long i = 0; i < events; i++) {
                int n = (int) (i % nodes);
                long time = 1_795_000_000_000_000L + (i / nodes) * 100 * nodes + n * 100;
                rows.append(firstSource + n).append('\t').append(time).append('\t');
                if (n % 12 < 8) {
                    rows.append(rnd.nextGaussian()).append("\t3\n");
                } else if (n % 12 < 11) {
                    for (int k = 0; k < 12; k++) {
                        rows.append(k > 0 ? "," : "").append(rnd.nextGaussian());
                    }
                    rows.append("\t6\n");
                } else {
                    rows.append(rnd.nextInt(100_000)).append("\t2\n");
                }
                if (rows.length() > (1 << 20) - 512) {
                    byte[] b = rows.toString().getBytes(StandardCharsets.UTF_8);
                    in.writeToCopy(b, 0, b.length);
                    rows.setLength(0);
                }
            }
            byte[] b = rows.toString().getBytes(StandardCharsets.UTF_8);
            in.writeToCopy(b, 0, b.length);
            in.endCopy();
        } finally {
            if (in.isActive()) {
                in.cancelCopy();
            }
        }
    }
}
