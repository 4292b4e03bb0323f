package org.fdnet.runtime.library;

import org.fdnet.event.ValueType;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Writes one value to all its outputs when it starts (and at each period, if it has one): parameter
 * {@code value} (required), typed by its {@code type} attribute; untyped, it is a number if it reads as
 * one, a vector if it reads as several, else a text. Useful for set-points and intentions.
 */
public class Constant extends Relation {
    public static final ParameterSpec<String> VALUE = ParameterSpec.text("value")
            .describe("the value written, typed by its type attribute (untyped: a number, numbers, else a text)").live();

    private Value value;

    @Override
    protected void init(NodeParameters p) {
        String text = VALUE.read(p);
        ParameterType declared = null;
        for (Parameter param : p.all()) {
            if ("value".equals(param.name())) {
                declared = param.type();
            }
        }
        value = declared != null ? Value.parse(valueType(declared), text) : guess(text);
    }

    private static Value guess(String text) {
        try {
            return Value.parse(ValueType.DOUBLE, text);
        } catch (IllegalArgumentException notOne) {
            try {
                return Value.parse(ValueType.DOUBLES, text);
            } catch (IllegalArgumentException notSeveral) {
                return Value.of(text);
            }
        }
    }

    private static ValueType valueType(ParameterType t) {
        return switch (t) {
            case STRING -> ValueType.STRING;
            case BOOLEAN -> ValueType.BOOLEAN;
            case LONG -> ValueType.LONG;
            case DOUBLE -> ValueType.DOUBLE;
            case DOUBLES -> ValueType.DOUBLES;
            case BYTES -> ValueType.BYTES;
        };
    }

    @Override
    protected void compute(RelationContext context) {
        context.outputAll(value);
    }
}
