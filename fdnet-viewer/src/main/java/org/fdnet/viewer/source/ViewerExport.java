package org.fdnet.viewer.source;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.event.ValueType;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.logger.export.ExportRow;
import org.fdnet.logger.export.LongCsvSink;
import org.fdnet.logger.export.McapRunSink;
import org.fdnet.logger.export.RecordedNode;
import org.fdnet.logger.export.RecordedRun;
import org.fdnet.logger.export.RunSink;
import org.fdnet.logger.export.WideCsvSink;
import org.fdnet.netinfo.NodeKind;

/**
 * The viewer's Export: the history of chosen nodes over a time range of the common clock, asked of the logger
 * (its cache and database) and written by the logger's export sinks as MCAP, a long CSV table or a wide one — the
 * same files {@code fdnet export} writes.
 *
 * <pre>
 *   LoggerConnection.history(ids, range widened by the hosts' offsets) ─shifted, time order─▶ ExportRow ─▶ RunSink ─▶ file
 * </pre>
 */
public final class ViewerExport {
    /** The file formats offered. */
    public enum Format {
        MCAP("MCAP (Foxglove, PlotJuggler, Python)", ".mcap"),
        CSV("CSV, one line per value", ".csv"),
        WIDE_CSV("CSV, one column per node", ".csv");

        private final String label;
        private final String extension;

        Format(String label, String extension) {
            this.label = label;
            this.extension = extension;
        }

        public String extension() {
            return extension;
        }

        @Override
        public String toString() {
            return label;
        }
    }

    /** What was written: values and the file's bytes. */
    public record Written(long values, long bytes) {
    }

    private ViewerExport() {
    }

    /**
     * Writes the values of {@code nodes} (of {@code run}) with common-clock times in [{@code fromMicros},
     * {@code toMicros}] to {@code file} in {@code format}.
     */
    public static Written write(LoggerConnection connection, RunInfo run, List<LoggedNode> nodes, long fromMicros,
                                long toMicros, Format format, Path file) throws IOException {
        int[] ids = nodes.stream().mapToInt(LoggedNode::sourceId).toArray();
        long widen = 0;
        for (int id : ids) {
            widen = Math.max(widen, Math.abs(connection.clockOffsetOf(id)));
        }
        List<NetworkEvent> events = connection.history(ids, fromMicros - widen, toMicros + widen);
        events.removeIf(e -> e.time() < fromMicros || e.time() > toMicros);
        RecordedRun recorded = recordedRun(connection, run, nodes);
        try (OutputStream out = Files.newOutputStream(file)) {
            RunSink sink = switch (format) {
                case MCAP -> new McapRunSink(out);
                case CSV -> new LongCsvSink(out);
                case WIDE_CSV -> new WideCsvSink(out, typesOf(events, ids));
            };
            try (sink) {
                sink.begin(recorded);
                ExportRow row = new ExportRow();
                for (NetworkEvent e : events) {
                    if (e instanceof DataValueEvent d) {
                        sink.accept(row.data(d.sourceId(), d.time(), d.type(), d.value().text()));
                    } else if (e instanceof RelationValueEvent r) {
                        sink.accept(row.relation(r.sourceId(), r.time(), r.value()));
                    } else if (e instanceof NetworkCommandEvent c) {
                        sink.accept(row.command(c.sourceId(), c.time(), c.sourceType(), c.command().text(), c.paramsId(),
                                c.paramsType()));
                    }
                }
            }
            return new Written(sink.written(), sink.bytes());
        }
    }

    private static RecordedRun recordedRun(LoggerConnection connection, RunInfo run, List<LoggedNode> chosen) {
        Map<Integer, RecordedNode> nodes = new LinkedHashMap<>();
        List<LoggedNode> all = new ArrayList<>(chosen);
        if (run != null) {
            all.addAll(run.nodes());
        }
        for (LoggedNode n : all) {
            nodes.putIfAbsent(n.sourceId(), new RecordedNode(n.sourceId(), NodeKind.DATA, n.name().module(), n.name().node(),
                    run == null ? "" : run.hostOf(n), connection.clockOffsetOf(n.sourceId())));
        }
        if (run == null) {
            return new RecordedRun(0, "", "", 0, List.of(), null, null, List.of(), nodes);
        }
        return new RecordedRun(run.runId(), run.network(), "", run.startedMicros(),
                new ArrayList<>(new java.util.TreeSet<>(run.hostOfStream().values())), null, null,
                new ArrayList<>(run.hostOfStream().keySet()), nodes);
    }

    private static Map<Integer, ValueType> typesOf(List<NetworkEvent> events, int[] ids) {
        Map<Integer, ValueType> types = new LinkedHashMap<>();
        for (int id : ids) {
            for (NetworkEvent e : events) {
                if (e instanceof DataValueEvent d && d.sourceId() == id) {
                    types.put(id, d.type());
                    break;
                }
            }
        }
        return types;
    }
}
