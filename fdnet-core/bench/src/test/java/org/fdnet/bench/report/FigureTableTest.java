package org.fdnet.bench.report;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;

class FigureTableTest {
    private static final RunFacts RUN = new RunFacts("2026-11-28", "abc1234", "2 cores, 24 GiB, JDK 17.0.15", "0.10 → 0.80");
    private static final FigureSpec HOP = FigureSpec.of("core: hop", "µs", "hop ([0-9.]+)", "plain ([0-9.]+)",
            Target.atMost(2), true, "the engine's bookkeeping");
    private static final FigureSpec CHAIN = FigureSpec.of("core: chain", "firings/s", "chain ([0-9,]+)", null,
            Target.atLeast(1_000_000), false, "one shared core");
    private static final FigureSpec DRIFT = FigureSpec.of("roq: drift", "m", "drift ([0-9.]+)", null, null, true, "");

    private static String page(String table) {
        return "# Benchmarks\n\nintro\n\n" + FigureTable.START + "\n" + table + FigureTable.END + "\n\n## How to run\n";
    }

    @Test
    void shouldReadBackEveryCellOfTheRowsItWrote() {
        FigureTable table = new FigureTable(List.of(FigureRow.measured(HOP, 0.651, 0.05, RUN, "bin/fdnet bench core"),
                FigureRow.missing(CHAIN, "its line was not in the output (exit 1)", RUN, "bin/fdnet bench core")));
        FigureTable read = FigureTable.readFrom(table.writeInto(page("")));
        assertThat(read.rows()).isEqualTo(table.rows());
        assertThat(read.row("core: hop").number()).isEqualTo(0.651);
        assertThat(read.row("core: chain").number()).isNaN();
    }

    @Test
    void shouldRewriteOnlyWhatLiesBetweenTheMarkers() {
        String before = page("| figure | value |\n|---|---|\n");
        FigureTable table = new FigureTable(List.of(FigureRow.measured(HOP, 0.651, 0.05, RUN, "bin/fdnet bench core")));
        String after = table.writeInto(FigureTable.readFrom(table.writeInto(before)).writeInto(before));
        assertThat(after).startsWith("# Benchmarks\n\nintro\n\n" + FigureTable.START + "\n" + FigureRow.HEADER)
                .endsWith("| `bin/fdnet bench core` |\n" + FigureTable.END + "\n\n## How to run\n")
                .isEqualTo(table.writeInto(before));
    }

    @Test
    void shouldKeepTheRowsOfBenchmarksNotRunAndPutEveryRowInThePlansOrder() {
        FigureTable committed = new FigureTable(List.of(FigureRow.measured(DRIFT, 0.23, Double.NaN, RUN, "bin/fdnet bench roq"),
                FigureRow.measured(HOP, 0.9, 0.05, RUN, "old command"),
                FigureRow.measured(FigureSpec.of("gone: figure", "ms", "x", null, null, true, ""), 1, 1, RUN, "old")));
        FigureTable merged = committed.merge(List.of(FigureRow.measured(HOP, 0.651, 0.05, RUN, "new command")),
                List.of("core: hop", "core: chain", "roq: drift"));
        assertThat(merged.rows()).extracting(FigureRow::figure).containsExactly("core: hop", "roq: drift");
        assertThat(merged.row("core: hop").command()).isEqualTo("`new command`");
        assertThat(merged.row("roq: drift").value()).isEqualTo("0.230 m");
    }

    @Test
    void shouldNameTheMarkersAPageWithoutATableLacks() {
        assertThatThrownBy(() -> FigureTable.readFrom("# Benchmarks\n")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining(FigureTable.START).hasMessageContaining(FigureTable.END);
    }

    @Test
    void shouldRefuseARowThatHasNotTheTablesElevenCells() {
        assertThatThrownBy(() -> FigureTable.readFrom(page(FigureRow.HEADER + "\n| core: hop | 0.651 µs |\n")))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("11 cells, this one 2")
                .hasMessageContaining("| core: hop | 0.651 µs |");
    }

    @Test
    void shouldGiveEachRowItsRatioTargetAndVerdict() {
        FigureRow met = FigureRow.measured(HOP, 0.651, 0.05, RUN, "c");
        assertThat(met.ratio()).isEqualTo("13.0×");
        assertThat(met.target()).isEqualTo("≤ 2 µs");
        assertThat(met.verdict()).isEqualTo("met");
        FigureRow missed = FigureRow.measured(CHAIN, 915_172, Double.NaN, RUN, "c");
        assertThat(missed.value()).isEqualTo("915,172 firings/s");
        assertThat(missed.baseline()).isEqualTo("—");
        assertThat(missed.verdict()).isEqualTo("**not met**: one shared core");
        assertThat(FigureRow.measured(DRIFT, 0.23, Double.NaN, RUN, "c").verdict()).isEqualTo("measured");
        FigureSpec ratio = FigureSpec.of("rt: p99", "µs", "x", "y", Target.ratioAtMost(1.25), true, "the VM's scheduling");
        assertThat(FigureRow.measured(ratio, 57, 39, RUN, "c").verdict()).isEqualTo("**not met**: the VM's scheduling");
        assertThat(FigureRow.measured(ratio, 57, 39, RUN, "c").target()).isEqualTo("≤ 1.25× baseline");
        assertThat(FigureRow.measured(ratio, 40, 39, RUN, "c").verdict()).isEqualTo("met");
        assertThat(Target.ratioAtLeast(0.9).text("sim s/s")).isEqualTo("≥ 0.9× baseline");
        assertThat(Target.atLeast(1_000_000).text("firings/s")).isEqualTo("≥ 1,000,000 firings/s");
    }
}
