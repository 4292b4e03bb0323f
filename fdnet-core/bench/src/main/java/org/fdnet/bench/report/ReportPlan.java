package org.fdnet.bench.report;

import static org.fdnet.bench.report.FigureSpec.of;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Every benchmark the report runs, with its arguments and the figures it reads. The expressions follow the lines each
 * benchmark prints (its summary); a benchmark whose output changes shows "not measured" in the table until they are
 * brought along. The report's arguments shorten the longest benchmarks (fewer pushes, seeds and seconds than their own
 * defaults) so that the whole report takes about 20 minutes on a quiet 2-core machine; each benchmark's own defaults
 * remain the longer, more precise run.
 */
final class ReportPlan {
    private static final String NUM = "([0-9][0-9,]*(?:\\.[0-9]+)?)";
    private static final boolean LOWER = true;
    private static final boolean HIGHER = false;

    private ReportPlan() {
    }

    static List<ReportedBenchmark> benchmarks() {
        return List.of(
                new ReportedBenchmark("load",
                        List.of("bench", "load", "--runs", "5", "--cold-runs", "3"),
                        List.of("bench", "load", "--nodes", "1000", "--connections", "2000", "--runs", "2", "--cold-runs", "1"),
                        600, List.of(
                        of("load: load + validate 10,000 nodes, fresh JVM (median)", "ms",
                                "^load \\+ validate, fresh JVM\\s+" + NUM, "^baseline: bare SAX parse, fresh JVM\\s+" + NUM,
                                Target.atMost(1000), LOWER, "the fresh JVM's class loading and JIT warm-up, ~5× a bare parse"),
                        of("load: descendants query, first call in a fresh JVM", "ms",
                                "^descendants \\([0-9]+\\), first call in that JVM\\s+" + NUM,
                                "^baseline: BFS over int arrays\\s+-\\s+" + NUM,
                                Target.atMost(10), LOWER, "the traversal is not compiled yet on the first call"))),
                new ReportedBenchmark("core",
                        List.of("bench", "core"),
                        List.of("bench", "core", "--hops", "20000", "--warmup", "20000"),
                        600, List.of(
                        of("core: hop p50 on the writer's thread", "µs",
                                "FDNet, run on the writer's thread\\s+p50\\s+" + NUM, "baseline: plain Java calls\\s+p50\\s+" + NUM,
                                Target.atMost(2), LOWER, "the engine's bookkeeping per firing"),
                        of("core: 10-Relation chain, one thread", "firings/s",
                                "^\\s+FDNet\\s+" + NUM + " /s", "baseline: plain Java calls\\s+" + NUM + " /s",
                                Target.atLeast(1_000_000), HIGHER, "one core shared with the rest of the machine"))),
                new ReportedBenchmark("corba",
                        List.of("bench", "corba", "--seconds", "20"),
                        List.of("bench", "corba", "--samples", "2000", "--warmup", "500", "--seconds", "3",
                                "--idle-samples", "20"),
                        900, List.of(
                        of("corba: round trip A → B → A, p50", "µs",
                                "^FDNet round trip A -> B -> back \\(2 hops\\):\\s+p50\\s+" + NUM,
                                "^bare JacORB two-way call \\(baseline\\):\\s+p50\\s+" + NUM,
                                Target.ratioAtMost(1.3), LOWER, "idle CPUs waking for four thread hand-offs against the bare call's three (with --hold-cpu-latency: 0.96–1.31×)"),
                        of("corba: sustained A → B → probe, 0 lost", "values/s",
                                "^sustained cross-host rate \\(A -> B -> probe\\):\\s+" + NUM + " values/s.* 0 lost", null,
                                Target.atLeast(2_000_000), HIGHER, "one writer thread and three hosts' engines share two cores"))),
                new ReportedBenchmark("logger",
                        List.of("bench", "logger", "--seconds", "30", "--latency-seconds", "10", "--burst", "2000000",
                                "--tls-seconds", "5"),
                        List.of("bench", "logger", "--seconds", "5", "--latency-seconds", "3", "--burst", "200000",
                                "--tls-seconds", "2"),
                        900, LoggerFigures.FIGURES),
                new ReportedBenchmark("export",
                        List.of("bench", "export"),
                        List.of("bench", "export", "--events", "50000", "--rounds", "1"),
                        600, List.of(
                        of("export: a 1,000,000-row run to MCAP", "rows/s",
                                "^bench export: [0-9,]+ rows; baseline .*?; MCAP export " + NUM + " rows/s",
                                "^bench export: [0-9,]+ rows; baseline bare COPY \\(SELECT \\.\\.\\.\\) TO STDOUT " + NUM + " rows/s",
                                Target.ratioAtLeast(0.5), false, "the export encodes on one core while the server sorts on the other"))),
                new ReportedBenchmark("viewer",
                        List.of("bench", "viewer", "--seconds", "20"),
                        List.of("bench", "viewer", "--seconds", "3", "--series", "5"),
                        240, List.of(
                        of("viewer: 50 series × 1 kHz, frames/s", "frames/s",
                                "^VIEWER frames: [0-9]+ in [0-9.]+ s = " + NUM + " frames/s",
                                "^baseline static painting .*?: " + NUM + " frames/s",
                                Target.atLeast(25), HIGHER, "painting shares the cores with the writer and the logger"),
                        of("viewer: write → screen p99", "ms",
                                "^VIEWER write -> screen .*?p99 " + NUM + " ms",
                                "^baseline raw monitor stream.*?p99 " + NUM + " ms",
                                Target.atMost(1000), LOWER, "the monitor stream or the painting fell behind"))),
                new ReportedBenchmark("hi",
                        List.of("bench", "hi"),
                        List.of("bench", "hi", "--nodes", "100", "--connections", "200", "--runs", "1", "--frames", "20"),
                        600, List.of(
                        of("hi: open + lay out 1,000 nodes, first call", "ms",
                                "^open \\(read, validate\\) \\+ lay out \\(ELK\\)\\s+" + NUM,
                                "^baseline: bare ELK layered call\\s+" + NUM,
                                Target.atMost(2000), LOWER, "ELK's and the editor's classes load and compile on the first open"),
                        of("hi: open + lay out 1,000 nodes, median", "ms",
                                "^open \\(read, validate\\) \\+ lay out \\(ELK\\)\\s+[0-9.,]+\\s+" + NUM,
                                "^baseline: bare ELK layered call\\s+[0-9.,]+\\s+" + NUM,
                                Target.atMost(2000), LOWER, "the ELK layout itself"),
                        of("hi: repaint while dragging at zoom 1", "frames/s",
                                "at zoom 1 \\(names, antialiasing\\): " + NUM + " frames/s", null,
                                Target.atLeast(30), HIGHER, "text and antialiasing of every visible node"))),
                new ReportedBenchmark("rt",
                        List.of("bench", "rt", "--seconds", "30"),
                        List.of("bench", "rt", "--seconds", "3"),
                        300, List.of(
                        of("rt: joint loop wake-up p99", "µs",
                                "^roq-sim joint loop: .*? p99 " + NUM + " µs", "^baseline cyclictest: .*? p99 " + NUM + " µs",
                                Target.ratioAtMost(1.25), LOWER, "the virtual machine's scheduling, which cyclictest shares"),
                        of("rt: loop overruns over 1 ms", "overruns",
                                "^roq-sim joint loop: .*overruns " + NUM, null,
                                Target.atMost(0), LOWER, "this machine is not real time: the host preempts the VM"))),
                new ReportedBenchmark("sim",
                        List.of("bench", "sim", "--seconds", "30"),
                        List.of("bench", "sim", "--seconds", "3"),
                        300, List.of(
                        of("sim: tick as shipped (range sensors on)", "sim s/s",
                                "^full tick with IR, sonar, depth rays\\s+" + NUM + " sim s per wall s",
                                "^baseline: bare mj_step loop\\s+" + NUM + " sim s per wall s",
                                Target.ratioAtLeast(0.9), HIGHER, "the range sensors' rays cost beside mj_step"),
                        of("sim: real-time factor of the tick as shipped", "× real time",
                                "^full tick with IR, sonar, depth rays\\s+" + NUM + " sim s per wall s", null,
                                Target.atLeast(10), HIGHER, "MuJoCo's step on a shared core"))),
                RoqFigures.AB, RoqFigures.PUSH, RoqFigures.HEADING, RoqFigures.BREAKTHROUGHS);
    }

    /** Every figure by its label, in the table's order. */
    static Map<String, FigureSpec> figures() {
        Map<String, FigureSpec> all = new LinkedHashMap<>();
        for (ReportedBenchmark b : benchmarks()) {
            for (FigureSpec f : b.figures()) {
                if (all.put(f.label(), f) != null) {
                    throw new IllegalStateException("two figures are labelled " + f.label());
                }
            }
        }
        return all;
    }
}
