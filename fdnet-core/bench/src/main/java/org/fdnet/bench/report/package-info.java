/**
 * {@code fdnet bench report}: every benchmark run once, its figures read from its own output, and the table in
 * docs/benchmarks.md rewritten with them, each figure beside its same-run baseline, its target and the run's date,
 * commit, machine and load.
 *
 * <pre>
 *   ReportPlan (benchmarks, their report-length arguments, the FigureSpecs to read)
 *      │ for each benchmark
 *      ▼
 *   BenchmarkProcess: bin/fdnet bench NAME ARGS (a child, as a user runs it) ──▶ its output lines, load before/after
 *      │ FigureSpec.read(lines)
 *      ▼
 *   FigureRow (figure, baseline, ratio, target, verdict, date, commit, machine, load, command)
 *      │
 *      ├──▶ Regressions.between(committed FigureTable, new rows) ──▶ "regression" lines (≥ 15 % worse)
 *      └──▶ FigureTable.merge(new rows).writeInto(docs/benchmarks.md) (rows of benchmarks not run are kept)
 * </pre>
 */
package org.fdnet.bench.report;
