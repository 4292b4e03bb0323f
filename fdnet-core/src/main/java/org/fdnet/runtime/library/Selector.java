package org.fdnet.runtime.library;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Passes one of its choices to all outputs. The selecting input is the one named by {@code select}
 * (default: the first input); it holds the index among the other inputs, in order (a boolean selects 0
 * for false, 1 for true; a number is rounded). An index outside the choices is reported and writes nothing.
 */
public class Selector extends Relation {
    public static final ParameterSpec<String> SELECT = ParameterSpec.text("select").defaultDescribed("the first input")
            .describe("the input that holds the index of the choice passed on");

    private String selectName;

    @Override
    protected void init(NodeParameters p) {
        selectName = SELECT.read(p);
    }

    @Override
    protected void compute(RelationContext context) {
        int s = selectName == null ? 0 : context.inputIndex(selectName);
        if (s < 0 || s >= context.inputCount()) {
            throw new IllegalStateException(context.self() + " has no selecting input"
                    + (selectName == null ? "" : " '" + selectName + "'"));
        }
        Value selector = context.input(s);
        if (selector == null) {
            context.report("waiting for " + context.inputRef(s));
            return;
        }
        long index = selector.asLong();
        int choices = context.inputCount() - 1;
        if (index < 0 || index >= choices) {
            context.report("index " + index + " is outside the " + choices + " choices");
            return;
        }
        int input = (int) index >= s ? (int) index + 1 : (int) index;
        Value chosen = context.input(input);
        if (chosen == null) {
            context.report("choice " + index + " (" + context.inputRef(input) + ") is missing");
            return;
        }
        context.report("choice " + index);
        context.outputAll(chosen);
    }
}
