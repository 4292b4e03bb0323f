package org.fdnet.bench.report;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Figures that came out at least {@link #WORSE} worse than the committed table's: lower when higher is better, higher
 * when lower is better. 15 % is above the run-to-run spread of most figures on a quiet machine, so a line here is worth
 * a look; figures the committed table has no number for are not judged; a figure that should be low and was 0 regresses
 * when it is not 0 any more.
 */
final class Regressions {
    static final double WORSE = 0.15;

    private Regressions() {
    }

    /** One line per regression, e.g. {@code core: chain: 915,172 firings/s, committed 3,392,320 firings/s (73 % worse)}. */
    static List<String> between(FigureTable committed, List<FigureRow> fresh, Map<String, FigureSpec> specs) {
        List<String> lines = new ArrayList<>();
        for (FigureRow row : fresh) {
            FigureRow old = committed.row(row.figure());
            FigureSpec spec = specs.get(row.figure());
            if (old == null || spec == null) {
                continue;
            }
            double before = old.number();
            double now = row.number();
            if (Double.isNaN(before) || Double.isNaN(now)) {
                continue;
            }
            if (before == 0) {
                if (spec.lowerIsBetter() && now > 0) {
                    lines.add(row.figure() + ": " + row.value() + ", committed " + old.value());
                }
                continue;
            }
            double worse = spec.lowerIsBetter() ? (now - before) / before : (before - now) / before;
            if (worse >= WORSE) {
                lines.add(String.format(Locale.ROOT, "%s: %s, committed %s (%.0f %% worse)", row.figure(), row.value(),
                        old.value(), worse * 100));
            }
        }
        return lines;
    }
}
