package org.fdnet.runtime;

import java.util.List;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;

/**
 * A node's parameters as its class reads them. A parameter the file types ({@code type="double"}) was
 * checked when the network was loaded; an untyped one is a string that this class converts on request.
 * Every failure is a {@link ParameterException} naming the node, the parameter and the bad value. A node class
 * declares its parameters as {@link ParameterSpec}s and reads them with {@link ParameterSpec#read}; the typed
 * getters here serve classes that declare nothing.
 */
public final class NodeParameters {
    private final NodeRef node;
    private final List<Parameter> parameters;

    public NodeParameters(NodeRef node, List<Parameter> parameters) {
        this.node = node;
        this.parameters = List.copyOf(parameters);
    }

    public static NodeParameters of(NodeRef node, NodeInfo info) {
        return new NodeParameters(node, info.parameters());
    }

    public NodeRef node() {
        return node;
    }

    public List<Parameter> all() {
        return parameters;
    }

    public boolean has(String name) {
        return find(name) != null;
    }

    /** The raw text of a named parameter, or {@code null}. */
    public String text(String name) {
        Parameter p = find(name);
        return p == null ? null : p.value();
    }

    /** The raw text of the {@code index}-th parameter (named or not), in file order. */
    public String positional(int index) {
        return index < parameters.size() ? parameters.get(index).value() : null;
    }

    public String string(String name, String fallback) {
        String t = text(name);
        return t == null ? fallback : t;
    }

    public String requireString(String name) {
        String t = text(name);
        if (t == null) {
            throw missing(name, "a text");
        }
        return t;
    }

    public double doubleValue(String name, double fallback) {
        return has(name) ? requireDouble(name) : fallback;
    }

    public double requireDouble(String name) {
        return (Double) typed(name, ParameterType.DOUBLE, "a number");
    }

    public long longValue(String name, long fallback) {
        return has(name) ? requireLong(name) : fallback;
    }

    public long requireLong(String name) {
        return (Long) typed(name, ParameterType.LONG, "a whole number");
    }

    public boolean booleanValue(String name, boolean fallback) {
        return has(name) ? (Boolean) typed(name, ParameterType.BOOLEAN, "true or false") : fallback;
    }

    public double[] doubles(String name, double[] fallback) {
        return has(name) ? requireDoubles(name) : fallback;
    }

    public double[] requireDoubles(String name) {
        return (double[]) typed(name, ParameterType.DOUBLES, "numbers separated by commas or spaces");
    }

    /** The parameter parsed as {@code type}, whatever the file declared (a long may be read as a double). */
    private Object typed(String name, ParameterType type, String expected) {
        Parameter p = find(name);
        if (p == null) {
            throw missing(name, expected);
        }
        try {
            return type.parse(p.value());
        } catch (IllegalArgumentException e) {
            throw new ParameterException(node.spelledOut() + ": parameter '" + name + "' must be " + expected
                    + ", was '" + p.value() + "'", e);
        }
    }

    /**
     * A refusal of two parameters that do not fit together, each fine on its own (a lower bound above an upper
     * one, two lists of different lengths, one of two alternatives required): the message names module, node, both
     * parameters with their values, and the rule.
     *
     * @param first  one parameter of the rule
     * @param second the other
     * @param rule   what must hold between them, e.g. {@code "low must not be above high"}
     * @return the exception to throw from {@code init}
     */
    public ParameterException conflict(ParameterSpec<?> first, ParameterSpec<?> second, String rule) {
        return new ParameterException(node.spelledOut() + ": parameters " + given(first) + " and " + given(second)
                + " do not fit together: " + rule);
    }

    private String given(ParameterSpec<?> spec) {
        String t = text(spec.name());
        return "'" + spec.name() + "' (" + (t != null ? t.strip() : spec.defaultText() != null
                ? "default " + spec.defaultText() : "not given") + ")";
    }

    /** A refusal of one parameter, worded {@code module 'M', node 'N': parameter 'P' WHY}. */
    ParameterException problem(String name, String why) {
        return new ParameterException(node.spelledOut() + ": parameter '" + name + "' " + why);
    }

    private ParameterException missing(String name, String expected) {
        return problem(name, "is required: it must be " + expected);
    }

    private Parameter find(String name) {
        for (Parameter p : parameters) {
            if (name.equals(p.name())) {
                return p;
            }
        }
        return null;
    }

    @Override
    public String toString() {
        return node + " " + parameters;
    }
}
