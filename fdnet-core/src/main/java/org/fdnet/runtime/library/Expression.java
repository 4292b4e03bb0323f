package org.fdnet.runtime.library;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Computes an arithmetic expression of its inputs (see {@link ExpressionParser} for the language) and
 * writes the result to every output: a number, or a vector for a posture. Parameter {@code expression}
 * (required). When an input the expression reads is missing, the Relation skips the firing and reports
 * {@code waiting for inN}. Example: {@code 0.8 * in0 + 0.2 * in1}, {@code mean(in0) + 0.05 * [1, -1, -1, 1] * sin(2*pi*t)}.
 */
public class Expression extends Relation {
    public static final ParameterSpec<ExpressionParser.Node> EXPRESSION = ParameterSpec.parsed("expression",
            "an expression of the inputs (in0, in1, ... or their names)", ExpressionParser::parse)
            .describe("what is computed and written to every output").live();

    private ExpressionParser.Node compiled;

    @Override
    protected void init(NodeParameters parameters) {
        compiled = EXPRESSION.read(parameters);
    }


    @Override
    protected void compute(RelationContext context) {
        MissingInput.Env env = new MissingInput.Env(context);
        double[] result;
        try {
            result = compiled.eval(env);
        } catch (MissingInput missing) {
            context.report("waiting for " + missing.getMessage());
            return;
        }
        context.report("RUNNING");
        context.outputAll(result.length == 1 ? Value.of(result[0]) : Value.ofDoubles(result));
    }
}
