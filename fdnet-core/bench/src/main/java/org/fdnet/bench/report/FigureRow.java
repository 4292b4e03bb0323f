package org.fdnet.bench.report;

import java.util.ArrayList;
import java.util.List;

/**
 * One row of the table in docs/benchmarks.md, as text cells. {@link #measured} makes one from a run; {@link #parse}
 * reads one back from the committed file.
 */
record FigureRow(String figure, String value, String baseline, String ratio, String target, String verdict,
                 String date, String commit, String machine, String load, String command) {

    static final String HEADER = "| figure | value | baseline (same run) | ratio | target | verdict | date | commit "
            + "| machine | load start → end | command |\n|---|---|---|---|---|---|---|---|---|---|---|";
    static final String NONE = "—";

    /** The row for a figure read in a run; {@code baseline} NaN when there is none. */
    static FigureRow measured(FigureSpec spec, double value, double baseline, RunFacts run, String command) {
        double ratio = value / baseline;
        String verdict;
        if (spec.target() == null) {
            verdict = "measured";
        } else if (spec.target().met(value, ratio)) {
            verdict = "met";
        } else {
            verdict = "**not met**: " + spec.limit();
        }
        return new FigureRow(spec.label(), Figures.format(value) + " " + spec.unit(),
                Double.isNaN(baseline) ? NONE : Figures.format(baseline) + " " + spec.unit(),
                Double.isNaN(ratio) ? NONE : Figures.format(ratio) + "×",
                spec.target() == null ? NONE : spec.target().text(spec.unit()), verdict, run.date(), run.commit(),
                run.machine(), run.load(), "`" + command + "`");
    }

    /** The row for a figure its benchmark's output did not hold (the benchmark failed or its output changed). */
    static FigureRow missing(FigureSpec spec, String why, RunFacts run, String command) {
        return new FigureRow(spec.label(), NONE, NONE, NONE,
                spec.target() == null ? NONE : spec.target().text(spec.unit()), "**not measured**: " + why,
                run.date(), run.commit(), run.machine(), run.load(), "`" + command + "`");
    }

    /** The figure as a number (NaN when not measured): what regressions are judged on. */
    double number() {
        return Figures.parse(value);
    }

    String markdown() {
        return "| " + String.join(" | ", cells()) + " |";
    }

    private List<String> cells() {
        return List.of(figure, value, baseline, ratio, target, verdict, date, commit, machine, load, command);
    }

    /**
     * Reads a row written by {@link #markdown()}.
     *
     * @throws IllegalArgumentException naming the line when it has not the table's 11 cells
     */
    static FigureRow parse(String line) {
        String inner = line.strip();
        if (!inner.startsWith("|") || !inner.endsWith("|")) {
            throw new IllegalArgumentException("not a table row: " + line);
        }
        List<String> cells = new ArrayList<>();
        for (String cell : inner.substring(1, inner.length() - 1).split("\\|", -1)) {
            cells.add(cell.strip());
        }
        if (cells.size() != 11) {
            throw new IllegalArgumentException("a row of the figures table has 11 cells, this one " + cells.size()
                    + ": " + line);
        }
        return new FigureRow(cells.get(0), cells.get(1), cells.get(2), cells.get(3), cells.get(4), cells.get(5),
                cells.get(6), cells.get(7), cells.get(8), cells.get(9), cells.get(10));
    }
}
