package org.fdnet.bench.report;

import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * One figure of a benchmark's output: where to read it and its baseline (a regular expression whose group 1 is the
 * number, matched against each output line until one matches), its unit, its target and which way is better.
 *
 * @param label         the table's name for it, unique in the report, e.g. {@code core: hop p50 on the writer's thread}
 * @param unit          the figure's unit as the table shows it
 * @param figure        finds the figure in the output
 * @param baseline      finds the same-run baseline, or null when the benchmark measures none for it
 * @param target        what it must reach, or null when it is only measured
 * @param lowerIsBetter which way a change is a regression
 * @param limit         one line: what limits it where the target is not met
 */
record FigureSpec(String label, String unit, Pattern figure, Pattern baseline, Target target, boolean lowerIsBetter,
                  String limit) {

    static FigureSpec of(String label, String unit, String figure, String baseline, Target target,
                         boolean lowerIsBetter, String limit) {
        return new FigureSpec(label, unit, Pattern.compile(figure), baseline == null ? null : Pattern.compile(baseline),
                target, lowerIsBetter, limit);
    }

    /** The figure read from {@code output}; empty when no line holds it. */
    Optional<Double> readFigure(List<String> output) {
        return find(figure, output);
    }

    /** The baseline read from {@code output}; empty when the figure has none or no line holds it. */
    Optional<Double> readBaseline(List<String> output) {
        return baseline == null ? Optional.empty() : find(baseline, output);
    }

    private static Optional<Double> find(Pattern p, List<String> output) {
        for (String line : output) {
            Matcher m = p.matcher(line);
            if (m.find()) {
                return Optional.of(Figures.parse(m.group(1)));
            }
        }
        return Optional.empty();
    }
}
