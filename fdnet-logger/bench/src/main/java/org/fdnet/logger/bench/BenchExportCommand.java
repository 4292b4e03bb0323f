package org.fdnet.logger.bench;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.fdnet.logger.export.ExportSelection;
import org.fdnet.logger.export.ExportSummary;
import org.fdnet.logger.export.LongCsvSink;
import org.fdnet.logger.export.McapRunSink;
import org.fdnet.logger.export.RecordedRun;
import org.fdnet.logger.export.RunExport;
import org.fdnet.logger.export.StoredRows;
import org.fdnet.logger.export.StoredRuns;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.logger.store.EmbeddedDatabase;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fdnet bench export}: the export's speed against its baseline in the same run — a bare
 * {@code COPY (SELECT …) TO STDOUT} of the very SELECT the export streams (same rows, same join, same sort),
 * read to the end and thrown away, on a throwaway embedded PostgreSQL. Rounds alternate baseline and export; the
 * medians give the ratio.
 */
@Command(name = "export", mixinStandardHelpOptions = true,
        description = {"Export a recorded run of --events rows to MCAP (and CSV) against a bare COPY (SELECT ...) TO STDOUT",
            "of the same rows in the same run; prints both rates, the ratio (target >= 50%%) and the load average."})
public final class BenchExportCommand implements Callable<Integer> {
    @Option(names = "--events", defaultValue = "1000000", description = "rows in the run (default ${DEFAULT-VALUE})")
    long events;

    @Option(names = "--nodes", defaultValue = "24", description = "Datas in the run (default ${DEFAULT-VALUE})")
    int nodes;

    @Option(names = "--rounds", defaultValue = "3", description = "baseline/export rounds (default ${DEFAULT-VALUE})")
    int rounds;

    @Override
    public Integer call() throws Exception {
        Path work = Files.createTempDirectory("fdnet-bench-export");
        try (EmbeddedDatabase embedded = EmbeddedDatabase.startThrowaway(work.resolve("pg"))) {
            return run(embedded.target(), work);
        } finally {
            try (var files = Files.walk(work)) {
                files.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            }
        }
    }

    private int run(DatabaseTarget target, Path work) throws Exception {
        try (Connection c = target.open()) {
            System.out.printf(Locale.ROOT, "bench export: filling a run of %,d rows over %d Datas ...%n", events, nodes);
            long t0 = System.nanoTime();
            int run = ExportBenchRun.fill(c, events, nodes);
            System.out.printf(Locale.ROOT, "bench export: filled in %.1f s; %d rounds of bare COPY then MCAP export%n",
                    (System.nanoTime() - t0) / 1e9, rounds);
            RecordedRun recorded = new StoredRuns(c).load(run);
            ExportSelection all = ExportSelection.all();
            roundTrip(c, recorded, all, work); // warm up: the JIT, the database's caches
            double[] bare = new double[rounds];
            double[] mcap = new double[rounds];
            long bytes = 0;
            for (int r = 0; r < rounds; r++) {
                long b0 = System.nanoTime();
                long rows = new StoredRows(c).copyBare(recorded, all, OutputStream.nullOutputStream());
                bare[r] = rows / ((System.nanoTime() - b0) / 1e9);
                ExportSummary s = roundTrip(c, recorded, all, work);
                mcap[r] = s.rowsPerSecond();
                bytes = s.bytes();
                System.out.printf(Locale.ROOT, "  round %d: bare COPY %,.0f rows/s, MCAP export %,.0f rows/s (%.0f%%)%n",
                        r + 1, bare[r], mcap[r], 100 * mcap[r] / bare[r]);
            }
            ExportSummary csv;
            try (OutputStream out = Files.newOutputStream(work.resolve("bench.csv"))) {
                csv = new RunExport(c, line -> { }, 60_000).export(recorded, all, new LongCsvSink(out));
            }
            double bareMedian = median(bare);
            double mcapMedian = median(mcap);
            double ratio = mcapMedian / bareMedian;
            System.out.printf(Locale.ROOT, "bench export: %,d rows; baseline bare COPY (SELECT ...) TO STDOUT %,.0f rows/s;"
                    + " MCAP export %,.0f rows/s (%,d bytes, %.1f bytes/row) = %.0f%% of the baseline (target >= 50%%): %s%n",
                    events, bareMedian, mcapMedian, bytes, (double) bytes / Math.max(1, events), 100 * ratio,
                    ratio >= 0.5 ? "MET" : "NOT MET");
            System.out.printf(Locale.ROOT, "bench export: long CSV export %,.0f rows/s (%,d bytes)%n", csv.rowsPerSecond(), csv.bytes());
            System.out.printf(Locale.ROOT, "bench export: load average %s%n", loadAverage());
            return 0;
        }
    }

    private static ExportSummary roundTrip(Connection c, RecordedRun run, ExportSelection all, Path work) throws Exception {
        try (OutputStream out = Files.newOutputStream(work.resolve("bench.mcap"))) {
            return new RunExport(c, line -> { }, 60_000).export(run, all, new McapRunSink(out));
        }
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s[s.length / 2];
    }

    private static String loadAverage() {
        try {
            return Files.readString(Path.of("/proc/loadavg")).trim();
        } catch (IOException e) {
            return "unknown";
        }
    }
}
