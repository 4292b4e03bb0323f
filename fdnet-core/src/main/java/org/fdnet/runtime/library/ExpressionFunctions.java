package org.fdnet.runtime.library;

import java.util.List;
import java.util.function.DoubleUnaryOperator;
import java.util.function.Function;

/**
 * The functions {@link Expression} knows: {@code sin cos tan asin acos atan sqrt abs exp log floor ceil
 * round sign} (element by element), {@code atan2 pow min max} (two arguments, element by element),
 * {@code clamp(x, lo, hi)}, and on whole vectors {@code sum mean len norm}.
 */
final class ExpressionFunctions {
    private ExpressionFunctions() {
    }

    static ExpressionParser.Node call(String name, List<ExpressionParser.Node> args,
                                      Function<String, IllegalArgumentException> error) {
        DoubleUnaryOperator unary = switch (name) {
            case "sin" -> Math::sin;
            case "cos" -> Math::cos;
            case "tan" -> Math::tan;
            case "asin" -> Math::asin;
            case "acos" -> Math::acos;
            case "atan" -> Math::atan;
            case "sqrt" -> Math::sqrt;
            case "abs" -> Math::abs;
            case "exp" -> Math::exp;
            case "log" -> Math::log;
            case "floor" -> Math::floor;
            case "ceil" -> Math::ceil;
            case "round" -> a -> (double) Math.round(a);
            case "sign" -> Math::signum;
            default -> null;
        };
        if (unary != null) {
            arity(name, args, 1, error);
            ExpressionParser.Node a = args.get(0);
            return env -> Vectors.map(a.eval(env), unary);
        }
        Vectors.Op binary = switch (name) {
            case "atan2" -> Math::atan2;
            case "pow" -> Math::pow;
            case "min" -> Math::min;
            case "max" -> Math::max;
            default -> null;
        };
        if (binary != null) {
            arity(name, args, 2, error);
            ExpressionParser.Node a = args.get(0);
            ExpressionParser.Node b = args.get(1);
            return env -> Vectors.combine(a.eval(env), b.eval(env), binary);
        }
        switch (name) {
            case "clamp" -> {
                arity(name, args, 3, error);
                ExpressionParser.Node x = args.get(0);
                ExpressionParser.Node lo = args.get(1);
                ExpressionParser.Node hi = args.get(2);
                return env -> Vectors.combine(Vectors.combine(x.eval(env), lo.eval(env), Math::max), hi.eval(env), Math::min);
            }
            case "sum", "mean", "len", "norm" -> {
                arity(name, args, 1, error);
                ExpressionParser.Node a = args.get(0);
                return env -> {
                    double[] v = a.eval(env);
                    double s = 0;
                    for (double d : v) {
                        s += name.equals("norm") ? d * d : d;
                    }
                    return new double[] {switch (name) {
                        case "sum" -> s;
                        case "mean" -> s / v.length;
                        case "len" -> v.length;
                        default -> Math.sqrt(s);
                    }};
                };
            }
            default -> throw error.apply("unknown function '" + name + "'");
        }
    }

    private static void arity(String name, List<ExpressionParser.Node> args, int n,
                              Function<String, IllegalArgumentException> error) {
        if (args.size() != n) {
            throw error.apply(name + " takes " + n + " argument" + (n == 1 ? "" : "s") + ", not " + args.size());
        }
    }
}
