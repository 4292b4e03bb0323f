package org.fdnet.viewer.ui;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fdnet.logger.export.CsvField;
import org.fdnet.viewer.data.Series;

/**
 * Writes the samples of series within a time range as CSV, one row per sample:
 * {@code series,unit,time_us,value} (series in the order given, each in time order). Names with commas or
 * quotes are quoted. Answers the number of rows written.
 */
public final class CsvExport {
    private CsvExport() {
    }

    public static long write(Path file, List<Series> series, long from, long to) throws IOException {
        long rows = 0;
        try (BufferedWriter w = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            w.write("series,unit,time_us,value\n");
            for (Series s : series) {
                Series.Samples samples = s.range(from, to);
                String name = CsvField.quote(s.name());
                String unit = CsvField.quote(s.unit());
                for (int i = 0; i < samples.size(); i++) {
                    w.write(name);
                    w.write(',');
                    w.write(unit);
                    w.write(',');
                    w.write(Long.toString(samples.times()[i]));
                    w.write(',');
                    w.write(Double.toString(samples.values()[i]));
                    w.write('\n');
                    rows++;
                }
            }
        }
        return rows;
    }
}
