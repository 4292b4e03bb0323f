package org.fdnet.viewer.ui;

import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import javax.swing.table.AbstractTableModel;
import org.fdnet.viewer.source.RunInfo;

/**
 * The runs the logger recorded, newest first: network, hosts, when it started (the clock time; the whole date is
 * the row's tooltip) and how long it lasted (the span of its recorded values, filled in once measured).
 */
final class RunTableModel extends AbstractTableModel {
    private static final String[] COLUMNS = {"Network", "Hosts", "Started", "Length"};
    private static final DateTimeFormatter STARTED = DateTimeFormatter.ofPattern("HH:mm:ss")
            .withZone(ZoneId.systemDefault());

    private final List<RunInfo> runs = new ArrayList<>();
    private final Map<Integer, Long> lengthMicros = new HashMap<>();

    void setRuns(List<RunInfo> list) {
        runs.clear();
        runs.addAll(list);
        fireTableDataChanged();
    }

    List<RunInfo> runs() {
        return List.copyOf(runs);
    }

    RunInfo run(int row) {
        return runs.get(row);
    }

    int rowOf(int runId) {
        for (int i = 0; i < runs.size(); i++) {
            if (runs.get(i).runId() == runId) {
                return i;
            }
        }
        return -1;
    }

    void setLength(int runId, long micros) {
        lengthMicros.put(runId, micros);
        int row = rowOf(runId);
        if (row >= 0) {
            fireTableCellUpdated(row, 3);
        }
    }

    @Override
    public int getRowCount() {
        return runs.size();
    }

    @Override
    public int getColumnCount() {
        return COLUMNS.length;
    }

    @Override
    public String getColumnName(int column) {
        return COLUMNS[column];
    }

    @Override
    public Object getValueAt(int row, int column) {
        RunInfo r = runs.get(row);
        return switch (column) {
            case 0 -> r.network().isEmpty() ? "run " + r.runId() : r.network();
            case 1 -> r.hostCount();
            case 2 -> r.startedMicros() == 0 ? "-" : STARTED.format(Instant.ofEpochMilli(r.startedMicros() / 1000));
            default -> length(lengthMicros.get(r.runId()));
        };
    }

    static String length(Long micros) {
        if (micros == null) {
            return "…";
        }
        long s = Math.round(micros / 1e6);
        return s < 600 ? s + " s" : s / 60 + " min";
    }
}
