package org.fdnet.bench.report;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The figures table of docs/benchmarks.md: the rows between the two marker lines. Reading it back lets a report run
 * part of the benchmarks ({@code --only}) and keep the other rows, and judge regressions against what was committed.
 */
final class FigureTable {
    static final String START = "<!-- figures: written by bin/fdnet bench report; edit the benchmarks, not this table -->";
    static final String END = "<!-- end of figures -->";

    private final Map<String, FigureRow> rows;

    FigureTable(List<FigureRow> rows) {
        this.rows = new LinkedHashMap<>();
        rows.forEach(r -> this.rows.put(r.figure(), r));
    }

    /**
     * The table in {@code document}.
     *
     * @throws IllegalArgumentException when the markers are missing or a row between them is not one of the table's
     */
    static FigureTable readFrom(String document) {
        String[] lines = block(document).split("\n");
        List<FigureRow> rows = new ArrayList<>();
        for (String line : lines) {
            if (line.startsWith("| figure |") || line.startsWith("|---") || line.isBlank()) {
                continue;
            }
            rows.add(FigureRow.parse(line));
        }
        return new FigureTable(rows);
    }

    List<FigureRow> rows() {
        return List.copyOf(rows.values());
    }

    FigureRow row(String figure) {
        return rows.get(figure);
    }

    /** This table with {@code fresh} rows in place of the ones of the same figure, in {@code order}'s order. */
    FigureTable merge(List<FigureRow> fresh, List<String> order) {
        Map<String, FigureRow> merged = new LinkedHashMap<>(rows);
        fresh.forEach(r -> merged.put(r.figure(), r));
        List<FigureRow> sorted = new ArrayList<>();
        for (String figure : order) {
            if (merged.containsKey(figure)) {
                sorted.add(merged.remove(figure));
            }
        }
        // rows the plan no longer names are dropped: their figure is no longer measured
        return new FigureTable(sorted);
    }

    String markdown() {
        StringBuilder md = new StringBuilder(FigureRow.HEADER).append('\n');
        rows.values().forEach(r -> md.append(r.markdown()).append('\n'));
        return md.toString();
    }

    /** {@code document} with this table between its markers; nothing else changes. */
    String writeInto(String document) {
        block(document);
        int start = document.indexOf(START) + START.length();
        int end = document.indexOf(END);
        return document.substring(0, start) + "\n" + markdown() + document.substring(end);
    }

    private static String block(String document) {
        int start = document.indexOf(START);
        int end = document.indexOf(END);
        if (start < 0 || end < start) {
            throw new IllegalArgumentException("docs/benchmarks.md has no figures table: it needs the line " + START
                    + " and, after it, " + END);
        }
        return document.substring(start + START.length(), end);
    }
}
