package org.fdnet.bench.report;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class RegressionsTest {
    private static final RunFacts RUN = new RunFacts("2026-11-28", "abc1234", "2 cores", "0.1 → 0.2");
    private static final FigureSpec RATE = FigureSpec.of("rate", "values/s", "x", null, null, false, "");
    private static final FigureSpec LATENCY = FigureSpec.of("latency", "ms", "x", null, null, true, "");
    private static final FigureSpec OVERRUNS = FigureSpec.of("overruns", "overruns", "x", null, Target.atMost(0), true, "");
    private static final Map<String, FigureSpec> SPECS = Map.of("rate", RATE, "latency", LATENCY, "overruns", OVERRUNS);

    private static FigureRow row(FigureSpec spec, double value) {
        return FigureRow.measured(spec, value, Double.NaN, RUN, "c");
    }

    private static List<String> compare(FigureSpec spec, double committed, double now) {
        return Regressions.between(new FigureTable(List.of(row(spec, committed))), List.of(row(spec, now)), SPECS);
    }

    @Test
    void shouldReportAHigherIsBetterFigureThatFell15PercentOrMore() {
        assertThat(compare(RATE, 1_000_000, 800_000)).containsExactly("rate: 800,000 values/s, committed 1,000,000 values/s (20 % worse)");
        assertThat(compare(RATE, 1_000_000, 840_000)).hasSize(1);
        assertThat(compare(RATE, 1_000_000, 860_000)).isEmpty();
        assertThat(compare(RATE, 1_000_000, 2_000_000)).isEmpty();
    }

    @Test
    void shouldReportALowerIsBetterFigureThatRose15PercentOrMore() {
        assertThat(compare(LATENCY, 10, 11.6)).containsExactly("latency: 11.6 ms, committed 10 ms (16 % worse)");
        assertThat(compare(LATENCY, 10, 11.4)).isEmpty();
        assertThat(compare(LATENCY, 10, 2)).isEmpty();
    }

    @Test
    void shouldReportAFigureThatShouldBeZeroAndIsNotAnyMore() {
        assertThat(compare(OVERRUNS, 0, 3)).containsExactly("overruns: 3 overruns, committed 0 overruns");
        assertThat(compare(OVERRUNS, 0, 0)).isEmpty();
    }

    @Test
    void shouldJudgeNoFigureTheCommittedTableHasNoNumberFor() {
        FigureTable committed = new FigureTable(List.of(FigureRow.missing(RATE, "not run", RUN, "c")));
        assertThat(Regressions.between(committed, List.of(row(RATE, 1)), SPECS)).isEmpty();
        assertThat(Regressions.between(new FigureTable(List.of()), List.of(row(RATE, 1)), SPECS)).isEmpty();
    }
}
