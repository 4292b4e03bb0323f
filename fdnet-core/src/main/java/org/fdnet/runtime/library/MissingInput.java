package org.fdnet.runtime.library;

import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/** An expression read an input that is not in the running network: the firing is skipped, not failed. */
final class MissingInput extends RuntimeException {
    private static final long serialVersionUID = 1L;

    MissingInput(String name) {
        super(name, null, false, false);
    }

    /** Expression names over a Relation's inputs: {@code in0..}, node names, {@code t}. */
    static final class Env implements ExpressionParser.Env {
        private final RelationContext context;

        Env(RelationContext context) {
            this.context = context;
        }

        @Override
        public double[] variable(String name) {
            if (name.equals("t")) {
                return new double[] {context.seconds()};
            }
            int index = -1;
            if (name.startsWith("in") && name.length() > 2 && name.substring(2).chars().allMatch(Character::isDigit)) {
                String digits = name.substring(2);
                // in99999999999 is an input no Relation has, not a number format crash
                index = digits.length() > 9 ? Integer.MAX_VALUE : Integer.parseInt(digits);
                if (index >= context.inputCount()) {
                    throw new IllegalArgumentException(context.self() + " reads " + context.inputCount()
                            + " inputs; the expression uses " + name);
                }
            } else {
                index = context.inputIndex(name);
                if (index < 0) {
                    throw new IllegalArgumentException("the expression uses '" + name + "', which is neither in0.., t, pi, e "
                            + "nor the name of a Data " + context.self() + " reads");
                }
            }
            Value v = context.input(index);
            if (v == null) {
                throw new MissingInput(name + " (" + context.inputRef(index) + ")");
            }
            return v.type() == org.fdnet.event.ValueType.DOUBLES ? v.asDoubles() : new double[] {v.asDouble()};
        }
    }
}
