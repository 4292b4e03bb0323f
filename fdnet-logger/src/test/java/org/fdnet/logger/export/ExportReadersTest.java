package org.fdnet.logger.export;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.logger.PostgresPerClass;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Runs exported from a real PostgreSQL and read back by readers no one here wrote — Python's {@code mcap} and
 * {@code @mcap/core}'s indexed reader (summary, chunk indexes, CRCs) — which must agree with the database row for
 * row; random runs from empty to 100,000 events, every value type, three hosts with clock offsets, Japanese names,
 * rows stored out of time order. The CSV forms load in pandas with the database's row count.
 */
class ExportReadersTest {
    @RegisterExtension
    static final PostgresPerClass PG = new PostgresPerClass();

    private static McapReaders readers;

    @TempDir
    Path dir;

    @BeforeAll
    static void findReaders() {
        readers = new McapReaders();
    }

    @ParameterizedTest(name = "{0} events, {1} hosts, seed {2}")
    @CsvSource({"0, 1, 1", "1, 1, 2", "3000, 3, 3", "3000, 2, 4", "100000, 3, 5"})
    void shouldBeReadBackRowForRowByPythonAndTypescriptReaders(int events, int hosts, long seed) throws Exception {
        try (Connection c = PG.fixture().target().open()) {
            int run = SyntheticRun.write(c, seed, events, hosts);
            Path mcap = dir.resolve("run.mcap");
            ExportSummary summary = export(c, run, ExportSelection.all(), mcap, "mcap");
            Path expected = dir.resolve("expected.jsonl");
            long rows = SyntheticRun.expectedRows(c, run, expected);

            assertThat(summary.rows()).isEqualTo(rows);
            assertThat(summary.records()).isEqualTo(rows);
            String python = readers.python(mcap, expected, events > 100 ? new String[] {McapRunSink.STRUCTURE_TOPIC} : new String[0]);
            assertThat(python).startsWith("python mcap: OK").contains("rows " + rows).contains("synthetic-" + seed + ".fdn");
            String typescript = readers.typescript(mcap, expected);
            assertThat(typescript).startsWith("@mcap/core: OK").contains("rows " + rows).contains("1 attachments");
        }
    }

    @Test
    void shouldExportOnlyTheChosenNodesAndTimeRange() throws Exception {
        try (Connection c = PG.fixture().target().open()) {
            int run = SyntheticRun.write(c, 11, 2000, 2);
            RecordedRun recorded = new StoredRuns(c).load(run);
            RecordedNode first = recorded.nodes().values().iterator().next();
            long[] span = new StoredRuns(c).timeSpan(recorded);
            long lastTenth = span[1] - 100_000; // the last 0.1 s of the robot's 0.27 s (the other host is 5 s ahead)
            ExportSelection selection = new ExportSelection(List.of(first.sourceId()), false, lastTenth, span[1]);
            Path mcap = dir.resolve("part.mcap");
            ExportSummary summary = export(c, run, selection, mcap, "mcap");
            long rows = PG.fixture().count("SELECT count(*) FROM datavalue_log d JOIN fdnet_node n USING (sourceid)"
                    + " JOIN fdnet_run r ON r.run_id = n.run_id WHERE d.sourceid = " + first.sourceId()
                    + " AND d.time - r.clock_offset BETWEEN " + lastTenth + " AND " + span[1]);

            assertThat(rows).isPositive();
            assertThat(summary.records()).isEqualTo(rows);
            assertThat(readers.python(mcap, null)).startsWith("python mcap: OK " + rows + " messages, 2 channels");
        }
    }

    @Test
    void shouldWriteCsvTablesThatPandasLoadsWithTheDatabasesRowCount() throws Exception {
        try (Connection c = PG.fixture().target().open()) {
            int run = SyntheticRun.write(c, 21, 5000, 3);
            Path longCsv = dir.resolve("long.csv");
            export(c, run, ExportSelection.all(), longCsv, "csv");
            Path wideCsv = dir.resolve("wide.csv");
            export(c, run, ExportSelection.all(), wideCsv, "wide");
            String streams = "(SELECT run_id FROM fdnet_run WHERE network_run_id = (SELECT network_run_id FROM fdnet_run"
                    + " WHERE run_id = " + run + "))";
            long values = PG.fixture().count("SELECT (SELECT count(*) FROM datavalue_log WHERE sourceid IN (SELECT sourceid"
                    + " FROM fdnet_node WHERE run_id IN " + streams + ")) + (SELECT count(*) FROM procvalue_log WHERE sourceid"
                    + " IN (SELECT sourceid FROM fdnet_node WHERE run_id IN " + streams + "))");
            long scalarInstants = PG.fixture().count("SELECT count(DISTINCT d.time - r.clock_offset) FROM datavalue_log d"
                    + " JOIN fdnet_node n USING (sourceid) JOIN fdnet_run r ON r.run_id = n.run_id WHERE r.run_id IN " + streams
                    + " AND d.typevalue IN (1, 2, 3)");
            long scalarNodes = PG.fixture().count("SELECT count(DISTINCT d.sourceid) FROM datavalue_log d JOIN fdnet_node n"
                    + " USING (sourceid) WHERE n.run_id IN " + streams + " AND d.typevalue IN (1, 2, 3)");

            assertThat(readers.pandasShape(longCsv)).isEqualTo(values + " 5");
            assertThat(readers.pandasShape(wideCsv)).isEqualTo(scalarInstants + " " + (scalarNodes + 1));
        }
    }

    private static ExportSummary export(Connection c, int run, ExportSelection selection, Path file, String form)
            throws Exception {
        StoredRuns runs = new StoredRuns(c);
        RecordedRun recorded = runs.load(Integer.toString(run));
        List<String> progress = new ArrayList<>();
        try (OutputStream out = Files.newOutputStream(file)) {
            RunSink sink = switch (form) {
                case "mcap" -> new McapRunSink(out);
                case "wide" -> new WideCsvSink(out, runs.dataTypes(recorded));
                default -> new LongCsvSink(out);
            };
            return new RunExport(c, progress::add, 1000).export(recorded, selection, sink);
        }
    }
}
