package org.fdnet.logger.export;

import java.io.IOException;
import java.io.OutputStream;
import java.sql.Connection;
import java.sql.SQLException;
import org.fdnet.event.ValueType;
import org.postgresql.PGConnection;
import org.postgresql.copy.CopyOut;

/**
 * Streams a run's rows out of the database in time order on the run's common clock: one {@code COPY (SELECT …)
 * TO STDOUT} over the three event tables, each row's time less its host's clock offset, sorted by that time. The
 * server sends rows as it produces them and the driver hands over one row at a time, so a run larger than memory
 * exports in bounded memory; the server's sort spills to disk when it must.
 */
public final class StoredRows {
    /** Gets each row, in time order. */
    @FunctionalInterface
    public interface RowHandler {
        void row(ExportRow row) throws IOException;
    }

    private final Connection connection;

    public StoredRows(Connection connection) {
        this.connection = connection;
    }

    /**
     * The SELECT of {@code selection}'s rows of {@code run}: columns common time (µs), source id, kind (1 Data, 2
     * Relation, 3 structure), value type, value, and the structure change's source type, command, target, target
     * type; ordered by time, then kind, source and insertion.
     */
    public static String select(RecordedRun run, ExportSelection selection) {
        String streams = StoredRuns.join(run.streams());
        String where = " WHERE r.run_id IN (" + streams + ")";
        String range = selection.isWholeTime() ? ""
                : " AND %1$s.time - r.clock_offset BETWEEN " + selection.fromMicros() + " AND " + selection.toMicros();
        String nodes = selection.isAllNodes() ? "" : " AND %1$s.sourceid IN (" + StoredRuns.join(selection.sourceIds()) + ")";
        String from = " FROM %2$s %1$s JOIN fdnet_node n ON n.sourceid = %1$s.sourceid JOIN fdnet_run r ON r.run_id = n.run_id";
        StringBuilder sql = new StringBuilder("SELECT t, sourceid, kind, typevalue, value, sourcetype, command, params_id,"
                + " params_type FROM (");
        sql.append(String.format("SELECT d.time - r.clock_offset AS t, d.sourceid, 1 AS kind, d.typevalue, d.value,"
                + " NULL::text AS sourcetype, NULL::text AS command, NULL::text AS params_id, NULL::text AS params_type,"
                + " 0 AS seq" + from + where + range + nodes, "d", "datavalue_log"));
        sql.append(String.format(" UNION ALL SELECT p.time - r.clock_offset, p.sourceid, 2, NULL, p.value, NULL, NULL,"
                + " NULL, NULL, 0" + from + where + range + nodes, "p", "procvalue_log"));
        if (selection.structure()) {
            sql.append(String.format(" UNION ALL SELECT c.time - r.clock_offset, c.sourceid, 3, NULL, NULL, c.sourcetype,"
                    + " c.command, c.params_id, c.params_type, c.id_db" + from + where + range, "c", "netcommand_log"));
        }
        sql.append(") AS run_rows ORDER BY t, kind, sourceid, seq");
        return sql.toString();
    }

    /**
     * Memory the server may sort in before it spills to disk: the sort by common time holds the whole selection (a
     * million rows of vectors is ~100 MB). A session setting, so the baseline's COPY sorts alike.
     */
    static final String SORT_MEMORY = "SET work_mem = '256MB'";

    /** Reads every row of the selection in time order into {@code handler}; answers the number of rows. */
    public long read(RecordedRun run, ExportSelection selection, RowHandler handler) throws SQLException, IOException {
        sortInMemory();
        CopyOut copy = connection.unwrap(PGConnection.class).getCopyAPI()
                .copyOut("COPY (" + select(run, selection) + ") TO STDOUT");
        CopyTextFields fields = new CopyTextFields();
        ExportRow row = new ExportRow();
        long rows = 0;
        try {
            byte[] bytes;
            while ((bytes = copy.readFromCopy()) != null) {
                fields.split(bytes);
                long t = fields.number(0);
                int source = (int) fields.number(1);
                switch ((int) fields.number(2)) {
                    case 1 -> row.data(source, t, ValueType.fromCode((int) fields.number(3)), fields.text(4));
                    case 2 -> row.relation(source, t, fields.text(4));
                    default -> row.command(source, t, fields.text(5), fields.text(6), fields.text(7), fields.text(8));
                }
                handler.row(row);
                rows++;
            }
        } finally {
            if (copy.isActive()) {
                copy.cancelCopy();
            }
        }
        return rows;
    }

    private void sortInMemory() throws SQLException {
        try (java.sql.Statement s = connection.createStatement()) {
            s.execute(SORT_MEMORY);
        }
    }

    /** The bare baseline: the same SELECT copied to {@code out} as PostgreSQL's text, nothing else done. */
    public long copyBare(RecordedRun run, ExportSelection selection, OutputStream out) throws SQLException, IOException {
        return connection.unwrap(PGConnection.class).getCopyAPI()
                .copyOut("COPY (" + select(run, selection) + ") TO STDOUT", out);
    }
}
