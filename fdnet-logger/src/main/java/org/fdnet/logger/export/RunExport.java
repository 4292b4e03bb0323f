package org.fdnet.logger.export;

import java.io.IOException;
import java.sql.Connection;
import java.sql.SQLException;
import java.util.function.Consumer;

/**
 * Exports one stored run: its rows streamed from the database in time order ({@link StoredRows}) into a
 * {@link RunSink}, with a progress line at most every {@code progressEveryMillis} and a summary at the end.
 *
 * <pre>
 *   PostgreSQL ─COPY (SELECT … ORDER BY common time) TO STDOUT─▶ StoredRows ─ExportRow─▶ RunSink ─▶ file
 *                                                                                 (McapRunSink ─▶ RunScene topics)
 * </pre>
 */
public final class RunExport {
    private final Connection connection;
    private final Consumer<String> progress;
    private final long progressEveryMillis;

    public RunExport(Connection connection, Consumer<String> progress, long progressEveryMillis) {
        this.connection = connection;
        this.progress = progress;
        this.progressEveryMillis = progressEveryMillis;
    }

    /** Writes {@code selection} of {@code run} into {@code sink} and closes it. */
    public ExportSummary export(RecordedRun run, ExportSelection selection, RunSink sink) throws SQLException, IOException {
        long started = System.nanoTime();
        long[] nextReport = {started + progressEveryMillis * 1_000_000L};
        long rows;
        try (sink) {
            sink.begin(run);
            rows = new StoredRows(connection).read(run, selection, row -> {
                sink.accept(row);
                if ((sink.written() & 0x3FFF) == 0) {
                    long now = System.nanoTime();
                    if (now >= nextReport[0]) {
                        nextReport[0] = now + progressEveryMillis * 1_000_000L;
                        progress.accept(String.format("export: %,d records, %,d channels, %,d bytes, %.1f s",
                                sink.written(), sink.channels(), sink.bytes(), (now - started) / 1e9));
                    }
                }
            });
        }
        return new ExportSummary(rows, sink.written(), sink.channels(), sink.bytes(), (System.nanoTime() - started) / 1e9);
    }
}
