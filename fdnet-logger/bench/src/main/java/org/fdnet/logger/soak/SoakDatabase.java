package org.fdnet.logger.soak;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.HashMap;
import java.util.Map;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.netinfo.NodeRef;

/**
 * What the soak asks the logger's database: rows of a node by its name, in the soak's time window (microseconds since
 * the epoch). Asked by name and window only — not by run or host — so the count holds whatever identifies a run.
 */
final class SoakDatabase {
    private static final String BY_VALUE = "SELECT d.value, count(*) FROM datavalue_log d JOIN fdnet_node n"
            + " ON n.sourceid = d.sourceid WHERE n.module = ? AND n.node = ? AND d.time >= ? AND d.time <= ?"
            + " GROUP BY d.value";
    private static final String ROWS = "SELECT count(*) FROM datavalue_log d JOIN fdnet_node n"
            + " ON n.sourceid = d.sourceid WHERE n.module = ? AND n.node = ? AND d.time >= ? AND d.time <= ?";

    private static final String LONGEST_GAP = "SELECT max(gap) FROM (SELECT d.time - lag(d.time) OVER (ORDER BY d.time)"
            + " AS gap FROM datavalue_log d JOIN fdnet_node n ON n.sourceid = d.sourceid WHERE n.module = ? AND n.node = ?"
            + " AND d.time >= ? AND d.time <= ?) g";

    private final DatabaseTarget target;
    private final long fromMicros;

    SoakDatabase(DatabaseTarget target, long fromMicros) {
        this.target = target;
        this.fromMicros = fromMicros;
    }

    /** For a node whose values are whole numbers: how many rows hold each value. */
    Map<Long, Integer> copiesByValue(NodeRef node) throws SQLException {
        Map<Long, Integer> copies = new HashMap<>();
        try (Connection c = open(); PreparedStatement s = window(c.prepareStatement(BY_VALUE), node);
             ResultSet rs = s.executeQuery()) {
            while (rs.next()) {
                copies.merge(Math.round(Double.parseDouble(rs.getString(1))), rs.getInt(2), Integer::sum);
            }
        }
        return copies;
    }

    long rows(NodeRef node) throws SQLException {
        try (Connection c = open(); PreparedStatement s = window(c.prepareStatement(ROWS), node);
             ResultSet rs = s.executeQuery()) {
            rs.next();
            return rs.getLong(1);
        }
    }

    /** The longest time between two consecutive rows of {@code node} from {@code fromMillis} to {@code toMillis}; -1 if none. */
    long longestGapMillis(NodeRef node, long fromMillis, long toMillis) throws SQLException {
        try (Connection c = open(); PreparedStatement s = c.prepareStatement(LONGEST_GAP)) {
            s.setString(1, node.module());
            s.setString(2, node.node());
            s.setLong(3, fromMillis * 1_000);
            s.setLong(4, toMillis * 1_000);
            try (ResultSet rs = s.executeQuery()) {
                rs.next();
                long gap = rs.getLong(1);
                return rs.wasNull() ? -1 : gap / 1_000;
            }
        }
    }

    private PreparedStatement window(PreparedStatement s, NodeRef node) throws SQLException {
        s.setString(1, node.module());
        s.setString(2, node.node());
        s.setLong(3, fromMicros);
        s.setLong(4, Long.MAX_VALUE);
        return s;
    }

    private Connection open() throws SQLException {
        DriverManager.setLoginTimeout(2);
        return DriverManager.getConnection(target.url(), target.user(), target.password());
    }
}
