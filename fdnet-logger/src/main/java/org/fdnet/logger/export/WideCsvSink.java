package org.fdnet.logger.export;

import java.io.IOException;
import java.io.OutputStream;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.fdnet.event.ValueType;

/**
 * A run as a wide table, what PlotJuggler and pandas load as it is: a {@code time} column (seconds since the epoch
 * on the run's common clock, µs precision) and one column per scalar Data (boolean as 0/1, integer, number), one
 * line per instant at which any of them changed; each column holds its node's latest value at that instant (empty
 * before its first). Columns are named {@code MODULE/NODE}, with {@code HOST:} before it where two hosts share the
 * name. Vectors, strings, bytes, Relations and structure changes are left to the long table and MCAP.
 */
public final class WideCsvSink extends CsvSink {
    private final Map<Integer, ValueType> columnTypes;
    private final Map<Integer, Integer> columnOf = new HashMap<>();
    private String[] current;
    private long time = Long.MIN_VALUE;
    private boolean pending;

    /** {@code columnTypes}: the value type of each Data by source id (scalar ones become columns, in this order). */
    public WideCsvSink(OutputStream stream, Map<Integer, ValueType> columnTypes) {
        super(stream);
        this.columnTypes = columnTypes;
    }

    static boolean isScalar(ValueType t) {
        return t == ValueType.DOUBLE || t == ValueType.LONG || t == ValueType.BOOLEAN;
    }

    @Override
    public void begin(RecordedRun run) throws IOException {
        List<RecordedNode> columns = columnTypes.entrySet().stream().filter(e -> isScalar(e.getValue()))
                .map(e -> run.node(e.getKey())).toList();
        Set<String> seen = new HashSet<>();
        Set<String> shared = new HashSet<>();
        for (RecordedNode n : columns) {
            if (!seen.add(n.label())) {
                shared.add(n.label());
            }
        }
        out.write("time");
        for (RecordedNode n : columns) {
            columnOf.put(n.sourceId(), columnOf.size());
            out.write(',');
            out.write(CsvField.quote(shared.contains(n.label()) ? n.host() + ":" + n.label() : n.label()));
        }
        out.write('\n');
        current = new String[columns.size()];
    }

    @Override
    public void accept(ExportRow row) throws IOException {
        if (row.kind != ExportRow.Kind.DATA || !isScalar(row.type)) {
            return;
        }
        Integer column = columnOf.get(row.sourceId);
        if (column == null) {
            return;
        }
        if (pending && row.time != time) {
            writeLine();
        }
        time = row.time;
        pending = true;
        String v = row.value;
        if (row.type == ValueType.BOOLEAN && v != null) {
            v = v.equals("true") ? "1" : "0";
        } else if (v != null && !ValueJson.isNumber(v, 0, v.length())) {
            v = switch (v) {
                case "NaN" -> "nan";
                case "Infinity" -> "inf";
                case "-Infinity" -> "-inf";
                default -> null; // text that is not of its type: no number to plot
            };
        }
        current[column] = v;
    }

    private void writeLine() throws IOException {
        long seconds = Math.floorDiv(time, 1_000_000L);
        long micros = Math.floorMod(time, 1_000_000L);
        out.write(Long.toString(seconds));
        out.write('.');
        String frac = Long.toString(micros);
        for (int i = frac.length(); i < 6; i++) {
            out.write('0');
        }
        out.write(frac);
        for (String v : current) {
            out.write(',');
            if (v != null) {
                out.write(v);
            }
        }
        out.write('\n');
        lines++;
    }

    @Override
    public int channels() {
        return current == null ? 0 : current.length;
    }

    @Override
    public void close() throws IOException {
        try {
            if (pending) {
                writeLine();
                pending = false;
            }
        } finally {
            super.close();
        }
    }
}
