package org.fdnet.bench.report;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * The plan reads the right numbers from each benchmark's real output: the samples under bench-output/ are what each
 * benchmark printed in a short run ({@code bench report --quick}'s arguments), so a figure read from the wrong line,
 * or a benchmark whose output no longer has the line, shows here.
 */
class ReportPlanTest {
    private static final Map<String, ReportedBenchmark> PLAN = ReportPlan.benchmarks().stream()
            .collect(Collectors.toMap(ReportedBenchmark::name, Function.identity()));

    private static List<String> output(String benchmark) throws IOException {
        try (InputStream in = ReportPlanTest.class.getResourceAsStream("/bench-output/" + benchmark + ".txt")) {
            assertThat(in).as("a sample of " + benchmark + "'s output").isNotNull();
            return new String(in.readAllBytes(), StandardCharsets.UTF_8).lines().toList();
        }
    }

    /** {figure, baseline} as the plan reads them from the sample (baseline NaN when none). */
    private static double[] read(String benchmark, String labelStart) throws IOException {
        List<String> out = output(benchmark);
        FigureSpec spec = PLAN.get(benchmark).figures().stream().filter(f -> f.label().startsWith(labelStart))
                .findFirst().orElseThrow(() -> new AssertionError("no figure " + labelStart + " in " + benchmark));
        return new double[] {spec.readFigure(out).orElseThrow(() -> new AssertionError(spec.label() + ": not read")),
                spec.readBaseline(out).orElse(Double.NaN)};
    }

    @Test
    void shouldReadEveryFigureOfEveryBenchmarkFromItsOutput() throws IOException {
        for (ReportedBenchmark b : ReportPlan.benchmarks()) {
            List<String> out = output(b.name());
            for (FigureSpec f : b.figures()) {
                assertThat(f.readFigure(out)).as(b.name() + ": " + f.label()).isPresent();
                if (f.baseline() != null) {
                    assertThat(f.readBaseline(out)).as(b.name() + ": baseline of " + f.label()).isPresent();
                }
            }
        }
    }

    @Test
    void shouldReadEachFigureAndItsBaselineFromTheRightLine() throws IOException {
        assertThat(read("load", "load: load + validate")).containsExactly(1428.48, 264.18);
        assertThat(read("load", "load: descendants")).containsExactly(6.78, 0.22);
        assertThat(read("core", "core: hop")).containsExactly(0.651, 0.050);
        assertThat(read("core", "core: 10-Relation")).containsExactly(915_172, 63_090_328);
        assertThat(read("corba", "corba: round trip")).containsExactly(185.9, 70.6);
        assertThat(read("corba", "corba: sustained")[0]).isEqualTo(932_371);
        assertThat(read("logger", "logger: sustained end to end")).containsExactly(274_651, 521_134);
        assertThat(read("logger", "logger: sustained / raw COPY")).containsExactly(274_651, 398_027);
        assertThat(read("logger", "logger: event → commit")[0]).isEqualTo(92.5);
        assertThat(read("logger", "logger: viewer query over TCP while")).containsExactly(0.59, 0.03);
        assertThat(read("logger", "logger: query in-process")).containsExactly(0.03, 0.05);
        assertThat(read("logger", "logger: viewer query over TCP, writer idle")).containsExactly(0.68, 0.05);
        assertThat(read("logger", "logger: events lost in the burst")[0]).isZero();
        assertThat(read("export", "export: a 1,000,000-row run")).containsExactly(195_724, 318_843);
        assertThat(read("viewer", "viewer: 50 series")).containsExactly(30.0, 191.4);
        assertThat(read("viewer", "viewer: write")).containsExactly(43.9, 7.7);
        assertThat(read("hi", "hi: open + lay out 1,000 nodes, first")).containsExactly(1700.4, 297.4);
        assertThat(read("hi", "hi: open + lay out 1,000 nodes, median")).containsExactly(235.8, 210.1);
        assertThat(read("hi", "hi: repaint")[0]).isEqualTo(42.9);
        assertThat(read("rt", "rt: joint loop")).containsExactly(57, 39);
        assertThat(read("rt", "rt: loop overruns")[0]).isZero();
        assertThat(read("sim", "sim: tick")).containsExactly(17.2, 16.8);
        assertThat(read("roq-ab", "roq (a): stepped")).containsExactly(8.4, 5.4);
        assertThat(read("roq-ab", "roq (a): a 40 s robot test")).containsExactly(19.2, 21.9);
        assertThat(read("roq-ab", "roq (b)")).containsExactly(1, 1);
        assertThat(read("roq-push", "roq push")[0]).isEqualTo(10.33);
        assertThat(read("roq-heading", "roq heading")).containsExactly(0.093, 0.090);
        assertThat(read("roq-breakthroughs", "roq crossing: fragile")).containsExactly(0, 0);
        assertThat(read("roq-breakthroughs", "roq crossing: walked")).containsExactly(0.146, 0.222);
        assertThat(read("roq-breakthroughs", "roq crossing: runs that fell")[0]).isZero();
    }

    @Test
    void shouldLabelEveryFigureOnce() {
        long figures = ReportPlan.benchmarks().stream().mapToLong(b -> b.figures().size()).sum();
        assertThat(ReportPlan.figures()).hasSize((int) figures);
    }

    @Test
    void shouldNameEveryBenchmarkOfThePlanInTheOnlyOptionsHelp() {
        String help = new CommandLine(new BenchReportCommand()).getUsageMessage(CommandLine.Help.Ansi.OFF);
        for (String name : PLAN.keySet()) {
            assertThat(help).as("--only's help").contains(name);
        }
    }
}
