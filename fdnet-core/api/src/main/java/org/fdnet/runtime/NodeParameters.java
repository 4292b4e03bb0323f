package org.fdnet.runtime;

import java.util.List;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;

/**
 * A node's parameters as the network file gives them, handed to {@code init}. A node class declares its parameters
 * as {@link ParameterSpec}s and reads each with its declaration ({@link ParameterSpec#read}); the engine has checked
 * every declared one before {@code init}. A rule between two parameters is refused with {@link #conflict}.
 *
 * <p>The typed getters ({@link #doubleValue}, {@link #requireLong}, ...) serve a class that declares nothing: they
 * read a parameter as an undeclared {@link ParameterSpec} of that type would, and refuse in the same words. A
 * parameter the file types ({@code type="double"}) was also checked when the network was loaded.
 */
public final class NodeParameters {
    private final NodeRef node;
    private final List<Parameter> parameters;

    /**
     * The parameters of one node.
     *
     * @param node       the node, named in every refusal
     * @param parameters its parameters, in file order
     */
    public NodeParameters(NodeRef node, List<Parameter> parameters) {
        this.node = node;
        this.parameters = List.copyOf(parameters);
    }

    /**
     * The parameters of a node as its definition gives them.
     *
     * @param node the node's name
     * @param info its definition
     * @return its parameters
     */
    public static NodeParameters of(NodeRef node, NodeInfo info) {
        return new NodeParameters(node, info.parameters());
    }

    /**
     * The node these parameters belong to.
     *
     * @return the node's module and name
     */
    public NodeRef node() {
        return node;
    }

    /**
     * Every parameter, named or positional, in file order.
     *
     * @return the parameters
     */
    public List<Parameter> all() {
        return parameters;
    }

    /**
     * Whether the file gives a parameter of that name.
     *
     * @param name the parameter's name
     * @return true when it is present
     */
    public boolean has(String name) {
        return find(name) != null;
    }

    /**
     * The raw text of a named parameter.
     *
     * @param name the parameter's name
     * @return its text as the file gives it, or {@code null} when absent
     */
    public String text(String name) {
        Parameter p = find(name);
        return p == null ? null : p.value();
    }

    /**
     * The raw text of a parameter by position, named or not, in file order (the original FDNet's anonymous
     * parameters).
     *
     * @param index the position, from 0
     * @return its text, or {@code null} when the node has fewer parameters
     */
    public String positional(int index) {
        return index < parameters.size() ? parameters.get(index).value() : null;
    }

    /**
     * A text parameter, or a fallback.
     *
     * @param name     the parameter's name
     * @param fallback the value when absent
     * @return the text, or {@code fallback}
     */
    public String string(String name, String fallback) {
        return ParameterSpec.text(name).readOr(this, fallback);
    }

    /**
     * A text parameter the node needs.
     *
     * @param name the parameter's name
     * @return its text
     * @throws ParameterException when it is absent
     */
    public String requireString(String name) {
        return ParameterSpec.text(name).read(this);
    }

    /**
     * A number, or a fallback.
     *
     * @param name     the parameter's name
     * @param fallback the value when absent
     * @return the number
     * @throws ParameterException when it is given but is not a number
     */
    public double doubleValue(String name, double fallback) {
        return ParameterSpec.number(name).readOr(this, fallback);
    }

    /**
     * A number the node needs.
     *
     * @param name the parameter's name
     * @return the number
     * @throws ParameterException when it is absent or not a number
     */
    public double requireDouble(String name) {
        return ParameterSpec.number(name).read(this);
    }

    /**
     * A whole number, or a fallback.
     *
     * @param name     the parameter's name
     * @param fallback the value when absent
     * @return the number
     * @throws ParameterException when it is given but is not a whole number
     */
    public long longValue(String name, long fallback) {
        return ParameterSpec.whole(name).readOr(this, fallback);
    }

    /**
     * A whole number the node needs.
     *
     * @param name the parameter's name
     * @return the number
     * @throws ParameterException when it is absent or not a whole number
     */
    public long requireLong(String name) {
        return ParameterSpec.whole(name).read(this);
    }

    /**
     * True or false ({@code yes}, {@code no} too), or a fallback.
     *
     * @param name     the parameter's name
     * @param fallback the value when absent
     * @return the flag
     * @throws ParameterException when it is given but is neither
     */
    public boolean booleanValue(String name, boolean fallback) {
        return ParameterSpec.flag(name).readOr(this, fallback);
    }

    /**
     * Numbers separated by commas or spaces, or a fallback.
     *
     * @param name     the parameter's name
     * @param fallback the value when absent
     * @return the numbers
     * @throws ParameterException when it is given but one of them is not a number
     */
    public double[] doubles(String name, double[] fallback) {
        return ParameterSpec.numbers(name).readOr(this, fallback);
    }

    /**
     * Numbers separated by commas or spaces that the node needs.
     *
     * @param name the parameter's name
     * @return the numbers
     * @throws ParameterException when it is absent or one of them is not a number
     */
    public double[] requireDoubles(String name) {
        return ParameterSpec.numbers(name).read(this);
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
