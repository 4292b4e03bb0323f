package org.fdnet.logger.export;

import java.io.IOException;
import java.io.OutputStream;

/**
 * A run as a long table, one line per value of a Data or a Relation: {@code time_us,host,module,node,value} (time
 * in µs since the epoch on the run's common clock; the value as the database stores it — a vector's elements
 * comma-separated inside quotes). Structure changes are not values and are left out.
 */
public final class LongCsvSink extends CsvSink {
    public static final String HEADER = "time_us,host,module,node,value";
    private RecordedRun run;
    private final java.util.Map<Integer, String> prefixOf = new java.util.HashMap<>();

    public LongCsvSink(OutputStream stream) {
        super(stream);
    }

    @Override
    public void begin(RecordedRun run) throws IOException {
        this.run = run;
        out.write(HEADER);
        out.write('\n');
    }

    @Override
    public void accept(ExportRow row) throws IOException {
        if (row.kind == ExportRow.Kind.COMMAND) {
            return;
        }
        out.write(Long.toString(row.time));
        out.write(prefixOf.computeIfAbsent(row.sourceId, id -> {
            RecordedNode n = run.node(id);
            return "," + CsvField.quote(n.host()) + "," + CsvField.quote(n.module()) + "," + CsvField.quote(n.node()) + ",";
        }));
        out.write(CsvField.quote(row.value));
        out.write('\n');
        lines++;
    }

    @Override
    public int channels() {
        return prefixOf.size();
    }
}
