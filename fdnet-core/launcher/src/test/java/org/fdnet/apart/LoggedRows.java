package org.fdnet.apart;

import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import org.fdnet.logger.store.DatabaseTarget;

/** What the apart tests ask the logger's database about one client's stream (a run's UUID) after the run. */
final class LoggedRows {
    private LoggedRows() {
    }

    /** The rows a stream's events became: values, Relation outputs, commands and named nodes — one per event. */
    static long rowsOf(DatabaseTarget db, String stream) throws SQLException {
        String where = sourcesOf(stream);
        return number(db, "SELECT (SELECT count(*) FROM datavalue_log" + where + ")"
                + " + (SELECT count(*) FROM procvalue_log" + where + ") + (SELECT count(*) FROM netcommand_log" + where + ") + (SELECT count(*) FROM fdnet_node"
                + where + " AND node IS NOT NULL)");
    }

    /** A stream's Data values committed from {@code fromMicros} to {@code toMicros} (µs since the epoch). */
    static long valuesBetween(DatabaseTarget db, String stream, long fromMicros, long toMicros) throws SQLException {
        return number(db, "SELECT count(*) FROM datavalue_log" + sourcesOf(stream) + " AND time BETWEEN " + fromMicros
                + " AND " + toMicros);
    }

    /** The longest time between two consecutive Data values of a stream, from {@code fromMicros} to {@code toMicros}. */
    static long longestGapMicros(DatabaseTarget db, String stream, long fromMicros, long toMicros) throws SQLException {
        return number(db, "SELECT coalesce(max(gap), 0) FROM (SELECT time - lag(time) OVER (ORDER BY time) AS gap"
                + " FROM datavalue_log" + sourcesOf(stream) + " AND time BETWEEN " + fromMicros + " AND " + toMicros
                + ") g");
    }

    static long number(DatabaseTarget db, String sql) throws SQLException {
        try (Connection c = db.open(); Statement s = c.createStatement(); ResultSet rs = s.executeQuery(sql)) {
            rs.next();
            return rs.getLong(1);
        }
    }

    private static String sourcesOf(String stream) {
        return " WHERE sourceid IN (SELECT n.sourceid FROM fdnet_node n JOIN fdnet_run r USING (run_id)"
                + " WHERE r.run_uuid = '" + stream + "')";
    }
}
