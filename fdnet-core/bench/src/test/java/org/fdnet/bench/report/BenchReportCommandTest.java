package org.fdnet.bench.report;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * The whole report against a stand-in project whose bin/fdnet prints each benchmark's recorded output (the samples of
 * ReportPlanTest): what it writes into the page, what it keeps, what it calls a regression and how it ends.
 */
class BenchReportCommandTest {
    private static final String HOME = "fdnet.home";

    @TempDir
    Path project;

    private String homeBefore;
    private Path page;

    @BeforeEach
    void standInProject() throws IOException {
        homeBefore = System.getProperty(HOME);
        System.setProperty(HOME, project.toString());
        Path samples = Files.createDirectories(project.resolve("samples"));
        for (String name : List.of("core", "sim")) {
            try (InputStream in = getClass().getResourceAsStream("/bench-output/" + name + ".txt")) {
                Files.copy(in, samples.resolve(name + ".txt"));
            }
        }
        Path launcher = Files.createDirectories(project.resolve("bin")).resolve("fdnet");
        // prints the recorded output of "bench NAME", nothing for a benchmark it has none of
        Files.writeString(launcher, "#!/bin/sh\nf=\"" + samples + "/$2.txt\"\n[ -f \"$f\" ] && cat \"$f\"\nexit 0\n");
        Files.setPosixFilePermissions(launcher, PosixFilePermissions.fromString("rwxr-xr-x"));
        page = Files.createDirectories(project.resolve("docs")).resolve("benchmarks.md");
        RunFacts old = new RunFacts("2026-01-01", "0000000", "2 cores", "0.10 → 0.20");
        FigureSpec hop = ReportPlan.figures().get("core: hop p50 on the writer's thread");
        FigureSpec drift = ReportPlan.figures().get("roq heading: off the course line with module Course (without it: baseline)");
        Files.writeString(page, "# Benchmarks\n\n" + new FigureTable(List.of(
                FigureRow.measured(hop, 0.3, 0.05, old, "bin/fdnet bench core"),
                FigureRow.measured(drift, 0.23, 0.48, old, "bin/fdnet bench roq --part heading")))
                .writeInto(FigureTable.START + "\n" + FigureTable.END + "\n") + "\n## How to run\n");
    }

    @AfterEach
    void restoreHome() {
        if (homeBefore == null) {
            System.clearProperty(HOME);
        } else {
            System.setProperty(HOME, homeBefore);
        }
    }

    private record Run(int exit, String output) {
    }

    private static Run report(String... args) {
        StringWriter out = new StringWriter();
        CommandLine cl = new CommandLine(new BenchReportCommand());
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(out));
        int exit = cl.execute(args);
        return new Run(exit, out.toString());
    }

    @Test
    void shouldRewriteTheRowsOfTheBenchmarksItRanAndKeepTheOthers() throws IOException {
        Run run = report("--only", "core,sim");
        assertThat(run.exit()).as(run.output()).isZero();
        FigureTable table = FigureTable.readFrom(Files.readString(page));
        FigureRow hop = table.row("core: hop p50 on the writer's thread");
        assertThat(hop.value()).isEqualTo("0.651 µs");
        assertThat(hop.baseline()).isEqualTo("0.050 µs");
        assertThat(hop.verdict()).isEqualTo("met");
        assertThat(hop.command()).isEqualTo("`bin/fdnet bench core`");
        assertThat(table.row("sim: tick as shipped (range sensors on)").value()).isEqualTo("17.2 sim s/s");
        assertThat(table.row("roq heading: off the course line with module Course (without it: baseline)").date())
                .as("a row of a benchmark not run stays as committed").isEqualTo("2026-01-01");
        assertThat(Files.readString(page)).startsWith("# Benchmarks\n\n").endsWith("\n## How to run\n");
    }

    @Test
    void shouldPrintAFigureFifteenPercentWorseThanTheCommittedOneAsARegression() {
        Run run = report("--only", "core", "--dry-run");
        assertThat(run.output()).contains("1 regression(s)")
                .contains("REGRESSION core: hop p50 on the writer's thread: 0.651 µs, committed 0.300 µs (117 % worse)")
                .contains("left as it was (--dry-run)");
    }

    @Test
    void shouldLeaveThePageAloneOnADryRun() throws IOException {
        String before = Files.readString(page);
        assertThat(report("--only", "core", "--dry-run").exit()).isZero();
        assertThat(Files.readString(page)).isEqualTo(before);
    }

    @Test
    void shouldMarkTheFiguresOfABenchmarkThatPrintedNoneAndExitOne() throws IOException {
        Run run = report("--only", "rt");
        assertThat(run.exit()).isEqualTo(1);
        assertThat(run.output()).contains("2 figure(s) not measured");
        assertThat(FigureTable.readFrom(Files.readString(page)).row("rt: joint loop wake-up p99").verdict())
                .isEqualTo("**not measured**: its line was not in the output (exit 0)");
    }

    @Test
    void shouldRefuseABenchmarkTheReportDoesNotRunNamingTheOnesItDoes() {
        Run run = report("--only", "nosuch");
        assertThat(run.exit()).isEqualTo(2);
        assertThat(run.output()).contains("--only: no benchmark nosuch in the report; it runs load, core, corba, logger");
    }
}
