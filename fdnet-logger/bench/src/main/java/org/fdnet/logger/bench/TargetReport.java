package org.fdnet.logger.bench;

import java.util.ArrayList;
import java.util.List;

/** The benchmark's figures beside their targets: each printed as it is measured, all again at the end. */
final class TargetReport {
    private record Row(String measure, String result, String target, Boolean met) {
    }

    private final List<Row> rows = new ArrayList<>();

    /** A figure with a target; {@code met} says whether it holds. */
    void check(String measure, String result, String target, boolean met) {
        add(new Row(measure, result, target, met));
    }

    /** A figure shown for reading the others (no target of its own). */
    void info(String measure, String result) {
        add(new Row(measure, result, "", null));
    }

    private void add(Row row) {
        rows.add(row);
        System.out.println("  => " + format(row));
        System.out.flush();
    }

    private static String format(Row r) {
        return r.met == null ? r.measure + ": " + r.result
                : r.measure + ": " + r.result + "  (target " + r.target + ": " + (r.met ? "met" : "NOT MET") + ")";
    }

    void printSummary() {
        System.out.println();
        System.out.println("summary:");
        for (Row r : rows) {
            System.out.println("  " + format(r));
        }
        long missed = rows.stream().filter(r -> r.met != null && !r.met).count();
        long targets = rows.stream().filter(r -> r.met != null).count();
        System.out.printf("%d of %d targets met%n", targets - missed, targets);
    }
}
