package org.fdnet.bench.report;

import java.util.ArrayList;
import java.util.List;

/**
 * A benchmark as the report runs it.
 *
 * @param name           what {@code --only} calls it, e.g. {@code roq-push}
 * @param args           its arguments after {@code bin/fdnet}, sized for the report (all of them together take about
 *                       20 minutes on a quiet 2-core machine)
 * @param quickArgs      the same figures from a run of seconds, for trying the report itself ({@code --quick})
 * @param timeoutSeconds how long the report waits before it kills the benchmark and reads what it printed
 * @param figures        what the table takes from its output
 */
record ReportedBenchmark(String name, List<String> args, List<String> quickArgs, long timeoutSeconds,
                         List<FigureSpec> figures) {

    /** The command as the table shows it. */
    String command(boolean quick) {
        List<String> words = new ArrayList<>();
        words.add("bin/fdnet");
        words.addAll(quick ? quickArgs : args);
        return String.join(" ", words);
    }
}
