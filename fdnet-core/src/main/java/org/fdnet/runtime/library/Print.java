package org.fdnet.runtime.library;

import java.io.PrintStream;
import java.util.Locale;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Prints its inputs on standard output, one line per firing: {@code [prefix] t=1.234s Module/Node=value ...}.
 * Parameters: {@code prefix} (default: the Relation's name), {@code every} (ms; at most one line per
 * this interval, default 0 = every firing). Give it a {@code period} to print at a steady pace.
 * Printing to the console is its purpose, so it writes to System.out rather than the log.
 */
public class Print extends Relation {
    public static final ParameterSpec<String> PREFIX = ParameterSpec.text("prefix").defaultDescribed("the node's name")
            .describe("the start of every line").live();
    public static final ParameterSpec<Long> EVERY = ParameterSpec.whole("every").unit("ms").atLeast(0).defaultValue(0L)
            .describe("print at most one line per this interval (0: every firing)").live();

    private String prefix;
    private long everyMicros;
    private long lastPrinted = Long.MIN_VALUE;
    private PrintStream out = System.out;

    @Override
    protected void init(NodeParameters p) {
        prefix = PREFIX.readOr(p, p.node().node());
        everyMicros = EVERY.read(p) * 1000;
    }

    /** For tests: where lines go. */
    void printTo(PrintStream stream) {
        this.out = stream;
    }

    @Override
    protected void compute(RelationContext context) {
        long now = context.now();
        if (lastPrinted != Long.MIN_VALUE && now - lastPrinted < everyMicros) {
            return;
        }
        lastPrinted = now;
        StringBuilder line = new StringBuilder("[").append(prefix).append("] ")
                .append(String.format(Locale.ROOT, "t=%.3fs", context.seconds()));
        for (int i = 0; i < context.inputCount(); i++) {
            Value v = context.input(i);
            line.append(' ').append(context.inputRef(i)).append('=').append(v == null ? "(missing)" : format(v));
        }
        out.println(line);
    }

    private static String format(Value v) {
        if (v.type() == org.fdnet.event.ValueType.DOUBLE) {
            return String.format(Locale.ROOT, "%.4f", v.asDouble());
        }
        if (v.type() == org.fdnet.event.ValueType.DOUBLES) {
            StringBuilder b = new StringBuilder("[");
            for (int i = 0; i < v.length(); i++) {
                b.append(i == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.4f", v.element(i)));
            }
            return b.append(']').toString();
        }
        return v.text();
    }
}
