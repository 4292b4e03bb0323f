package org.fdnet.runtime.library;

import java.util.HashMap;
import java.util.Map;
import org.fdnet.event.ValueType;
import org.fdnet.runtime.MessageRefusedException;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.ServantNode;
import org.fdnet.runtime.Servants;
import org.fdnet.runtime.Value;

/**
 * A Relation that serves what it knows to other Relations (thesis Appendix 2, servants): it offers a servant at
 * path {@code servant} that answers message {@code message} (default {@code evaluate}) with {@code expression}
 * evaluated on the message's argument {@code arg} and on the Datas this Relation reads as of its latest firing
 * ({@code in0..} or their names; see {@link ExpressionParser}). Example: {@code min(arg, 0.5 * Obstacle)}. Another
 * Relation, on any host, asks it with {@link ServantAsker} or {@code servants().sendMessage}. The servant leaves
 * the tree when the Relation leaves the network.
 */
public class ExpressionServant extends Relation {
    public static final ParameterSpec<String> SERVANT = ParameterSpec.text("servant")
            .describe("the path of the servant it offers");
    public static final ParameterSpec<String> MESSAGE = ParameterSpec.text("message").defaultValue("evaluate")
            .describe("the message it answers");
    public static final ParameterSpec<ExpressionParser.Node> EXPRESSION = ParameterSpec.parsed("expression",
            "an expression of arg and the inputs", ExpressionParser::parse)
            .describe("the answer, computed from the message's argument arg and the Datas it reads").live();

    private String path;
    private String message;
    private ExpressionParser.Node compiled;
    private volatile Map<String, double[]> known = Map.of();
    private Servants servants;
    private ServantNode offered;

    @Override
    protected void init(NodeParameters parameters) {
        path = SERVANT.read(parameters).strip();
        message = MESSAGE.read(parameters).strip();
        compiled = EXPRESSION.read(parameters);
    }

    @Override
    protected void compute(RelationContext context) {
        Map<String, double[]> now = new HashMap<>();
        for (int i = 0; i < context.inputCount(); i++) {
            Value v = context.input(i);
            if (v != null) {
                double[] value = v.type() == ValueType.DOUBLES ? v.asDoubles() : new double[] {v.asDouble()};
                now.put("in" + i, value);
                now.put(context.inputRef(i).node(), value);
            }
        }
        known = Map.copyOf(now);
        if (offered == null) {
            servants = context.servants();
            offered = servants.offer(path, this::answer);
            context.report("serving " + offered.path());
        }
    }

    private Value answer(String asked, Value argument) {
        if (!message.equals(asked)) {
            throw new MessageRefusedException("servant " + path + " answers '" + message + "', not '" + asked + "'");
        }
        Map<String, double[]> inputs = known;
        double[] result;
        try {
            result = compiled.eval(name -> {
                if (name.equals("arg")) {
                    return argument.type() == ValueType.DOUBLES ? argument.asDoubles() : new double[] {argument.asDouble()};
                }
                double[] v = inputs.get(name);
                if (v == null) {
                    throw new MessageRefusedException("servant " + path + " has no value of '" + name + "' yet");
                }
                return v;
            });
        } catch (IllegalArgumentException e) {
            throw new MessageRefusedException("servant " + path + ": " + e.getMessage());
        }
        return result.length == 1 ? Value.of(result[0]) : Value.ofDoubles(result);
    }

    @Override
    protected void close() {
        if (offered != null) {
            servants.withdraw(offered);
        }
    }
}
