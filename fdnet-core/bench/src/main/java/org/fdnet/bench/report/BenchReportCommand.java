package org.fdnet.bench.report;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

/**
 * {@code fdnet bench report}: runs the benchmarks one after another, each through bin/fdnet as a user runs it, and
 * rewrites the figures table of docs/benchmarks.md from their output. Prints each benchmark's output as it comes, then
 * the new table and every figure at least 15 % worse than the committed one.
 */
@Command(name = "report", mixinStandardHelpOptions = true,
        description = {"Run every benchmark (about 20 minutes on a quiet 2-core machine) and rewrite the figures table "
                + "of docs/benchmarks.md: figure, same-run baseline, ratio, target, verdict, date, commit, machine, "
                + "load average at start and end.",
                "Figures at least 15 %% worse than the committed table's are printed as regressions. Run it on a quiet "
                        + "machine: other work on the cores moves every figure."})
public final class BenchReportCommand implements Callable<Integer> {
    @Option(names = "--only", split = ",", paramLabel = "BENCHMARK",
            description = "run only these (load, core, corba, logger, export, viewer, hi, rt, sim, roq-ab, roq-push, "
                    + "roq-heading, roq-breakthroughs); the table keeps the other rows")
    List<String> only;

    @Option(names = "--quick", description = "each benchmark for seconds only, to try the report: prints the table "
            + "and the comparison, writes nothing")
    boolean quick;

    @Option(names = "--dry-run", description = "print the table and the comparison, do not rewrite the file")
    boolean dryRun;

    @Option(names = "--file", paramLabel = "FILE",
            description = "the page whose table is rewritten (default: docs/benchmarks.md of the project)")
    Path file;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        PrintWriter out = spec.commandLine().getOut();
        Path project = Path.of(System.getProperty("fdnet.home", ".")).toAbsolutePath().normalize();
        Path page = file != null ? file : project.resolve("docs").resolve("benchmarks.md");
        Path launcher = project.resolve("bin").resolve("fdnet");
        List<ReportedBenchmark> plan = selected();
        if (!Files.isExecutable(launcher)) {
            throw new ParameterException(spec.commandLine(), "bench report runs the benchmarks through " + launcher
                    + ", which is missing: run it as bin/fdnet bench report");
        }
        String document = Files.readString(page, StandardCharsets.UTF_8);
        FigureTable committed = FigureTable.readFrom(document); // fails early, before any benchmark, on a bad page

        String machine = MachineFacts.machine();
        String commit = MachineFacts.commit(project);
        Instant started = Instant.now();
        out.printf("fdnet bench report: %d benchmark(s)%s on %s, commit %s, load %s%n", plan.size(),
                quick ? " (quick: figures for trying the report only)" : "", machine, commit, MachineFacts.loadAverage());
        List<FigureRow> rows = new ArrayList<>();
        int failed = 0;
        for (int i = 0; i < plan.size(); i++) {
            ReportedBenchmark b = plan.get(i);
            String command = b.command(quick);
            out.printf("%n[%d/%d] %s%n", i + 1, plan.size(), command);
            out.flush();
            String loadBefore = MachineFacts.loadAverage();
            long t0 = System.nanoTime();
            BenchmarkProcess.Result result = BenchmarkProcess.run(launcher, quick ? b.quickArgs() : b.args(),
                    b.timeoutSeconds(), out);
            RunFacts facts = new RunFacts(MachineFacts.today(), commit, machine,
                    loadBefore + " → " + MachineFacts.loadAverage());
            String ending = result.timedOut() ? "killed after " + b.timeoutSeconds() + " s"
                    : "exit " + result.exitCode();
            out.printf("[%d/%d] %s: %s in %d s%n", i + 1, plan.size(), b.name(), ending, (System.nanoTime() - t0) / 1_000_000_000L);
            for (FigureSpec f : b.figures()) {
                Optional<Double> value = f.readFigure(result.output());
                if (value.isPresent()) {
                    rows.add(FigureRow.measured(f, value.get(), f.readBaseline(result.output()).orElse(Double.NaN),
                            facts, command));
                } else {
                    failed++;
                    rows.add(FigureRow.missing(f, "its line was not in the output (" + ending + ")", facts, command));
                }
            }
        }
        List<String> order = List.copyOf(ReportPlan.figures().keySet());
        FigureTable updated = committed.merge(rows, order);
        out.printf("%nfigures (%s, %d min):%n%s", quick ? "quick run" : "report",
                Duration.between(started, Instant.now()).toMinutes(), new FigureTable(rows).markdown());
        List<String> regressions = Regressions.between(committed, rows, ReportPlan.figures());
        out.println();
        if (regressions.isEmpty()) {
            out.println("no figure is 15 % or more worse than the committed table's");
        } else {
            out.printf("%d regression(s), 15 %% or more worse than the committed table:%n", regressions.size());
            regressions.forEach(r -> out.println("  REGRESSION " + r));
        }
        if (quick || dryRun) {
            out.println(page + " left as it was (" + (quick ? "--quick" : "--dry-run") + ")");
        } else {
            Files.writeString(page, updated.writeInto(document), StandardCharsets.UTF_8);
            out.println("rewrote the table of " + page);
        }
        if (failed > 0) {
            out.printf("%d figure(s) not measured: see the benchmarks' output above%n", failed);
        }
        out.flush();
        return failed > 0 ? 1 : 0;
    }

    private List<ReportedBenchmark> selected() {
        List<ReportedBenchmark> all = ReportPlan.benchmarks();
        if (only == null || only.isEmpty()) {
            return all;
        }
        Map<String, ReportedBenchmark> byName = new java.util.LinkedHashMap<>();
        all.forEach(b -> byName.put(b.name(), b));
        List<ReportedBenchmark> chosen = new ArrayList<>();
        for (String name : only) {
            ReportedBenchmark b = byName.get(name.strip());
            if (b == null) {
                throw new ParameterException(spec.commandLine(), "--only: no benchmark " + name + " in the report; it runs "
                        + String.join(", ", byName.keySet()));
            }
            chosen.add(b);
        }
        return chosen;
    }
}
