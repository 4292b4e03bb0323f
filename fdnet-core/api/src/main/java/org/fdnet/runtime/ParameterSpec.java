package org.fdnet.runtime;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.Function;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.netinfo.ValueRange;

/**
 * One parameter of a node class, declared once: its name, type, unit, default, range, description and whether it
 * may change while the network runs. The declaration is a {@code static final} field of the node's class; the
 * engine finds every such field ({@link DeclaredParameters}), checks a node's parameters against them before
 * {@code init}, lists them ({@code fdnet info --params}, the editor's node form) and refuses a live change of a
 * parameter that is not {@link #live()}. The class reads each value in {@code init}:
 *
 * <pre>{@code
 * public class Gain extends Relation {
 *     public static final ParameterSpec<Double> GAIN = ParameterSpec.number("gain").unit("1").range(0, 10)
 *             .defaultValue(1.0).describe("the factor the input is multiplied by").live();
 *     public static final ParameterSpec<String> INPUT = ParameterSpec.text("input").optional()
 *             .describe("the input to scale (default: the first)");
 *
 *     private double gain;
 *     private String input;
 *
 *     protected void init(NodeParameters p) {
 *         gain = GAIN.read(p);     // 1.0 when absent; a refusal naming module, node, parameter and range otherwise
 *         input = INPUT.read(p);   // null when absent
 *     }
 *     ...
 * }
 * }</pre>
 *
 * <p>A declaration is immutable: every method that shapes it returns a new one, so a declared field can be shared
 * and reused ({@code Relation.PERIOD.range(0, 0)} narrows the engine's own declaration for one class). Every refusal
 * is one {@link ParameterException} in one form, e.g. {@code module 'main', node 'Gait': parameter 'stride' must be
 * a number in [0, 0.3] m, was 0.5}. A rule that joins two parameters (one must not exceed the other) is checked in
 * {@code init} and refused with {@link NodeParameters#conflict}.
 *
 * @param <T> what {@link #read} returns: {@code Double}, {@code Long}, {@code Boolean}, {@code String},
 *            {@code double[]}, an enum, or what a {@link #parsed} declaration's parser makes
 */
public final class ParameterSpec<T> {
    /** The unit of a ratio or a gain, declared for the record but not written after numbers. */
    public static final String DIMENSIONLESS = "1";

    private final String name;
    private final ParameterType fileType;
    private final String expected;
    private final Function<String, T> parser;
    private boolean tellsParserMessage;
    private List<String> choices = List.of();
    private ValueRange range = ValueRange.ANY;
    private T alsoAllowed;
    private String unit = "";
    private T defaultValue;
    private String defaultText;
    private boolean defaultIsValue;
    private boolean optional;
    private String description = "";
    private boolean live;

    private ParameterSpec(String name, ParameterType fileType, String expected, Function<String, T> parser) {
        if (name == null || name.isBlank()) {
            throw new IllegalArgumentException("a parameter needs a name");
        }
        this.name = name;
        this.fileType = fileType;
        this.expected = expected;
        this.parser = parser;
    }

    private ParameterSpec<T> copy() {
        ParameterSpec<T> c = new ParameterSpec<>(name, fileType, expected, parser);
        c.tellsParserMessage = tellsParserMessage;
        c.choices = choices;
        c.range = range;
        c.alsoAllowed = alsoAllowed;
        c.unit = unit;
        c.defaultValue = defaultValue;
        c.defaultText = defaultText;
        c.defaultIsValue = defaultIsValue;
        c.optional = optional;
        c.description = description;
        c.live = live;
        return c;
    }

    /**
     * A number ({@code 0.3}, {@code -2}, {@code 1e-3}).
     *
     * @param name the parameter's name in the network file
     * @return a required declaration without range
     */
    public static ParameterSpec<Double> number(String name) {
        return new ParameterSpec<>(name, ParameterType.DOUBLE, "a number", t -> (Double) ParameterType.DOUBLE.parse(t));
    }

    /**
     * A whole number ({@code 3}, {@code -1}).
     *
     * @param name the parameter's name in the network file
     * @return a required declaration without range
     */
    public static ParameterSpec<Long> whole(String name) {
        return new ParameterSpec<>(name, ParameterType.LONG, "a whole number", t -> (Long) ParameterType.LONG.parse(t));
    }

    /**
     * True or false ({@code yes} and {@code no} are accepted too).
     *
     * @param name the parameter's name in the network file
     * @return a required declaration
     */
    public static ParameterSpec<Boolean> flag(String name) {
        return new ParameterSpec<>(name, ParameterType.BOOLEAN, "true or false",
                t -> (Boolean) ParameterType.BOOLEAN.parse(t));
    }

    /**
     * Free text (a node's name, a class name, an expression given to another parser later).
     *
     * @param name the parameter's name in the network file
     * @return a required declaration
     */
    public static ParameterSpec<String> text(String name) {
        return new ParameterSpec<>(name, ParameterType.STRING, "a text", t -> t);
    }

    /**
     * Numbers separated by commas or spaces ({@code 0.1, 0.2, 0.3}); a range applies to each of them.
     *
     * @param name the parameter's name in the network file
     * @return a required declaration without range
     */
    public static ParameterSpec<double[]> numbers(String name) {
        return new ParameterSpec<>(name, ParameterType.DOUBLES, "numbers separated by commas or spaces",
                t -> (double[]) ParameterType.DOUBLES.parse(t));
    }

    /**
     * One word out of a fixed list (any case is accepted; {@link #read} returns the word as listed).
     *
     * @param name    the parameter's name in the network file
     * @param options the words allowed
     * @return a required declaration
     */
    public static ParameterSpec<String> choice(String name, String... options) {
        List<String> allowed = List.of(options);
        ParameterSpec<String> spec = new ParameterSpec<>(name, ParameterType.STRING,
                "one of " + String.join(", ", allowed), t -> allowed.stream().filter(o -> o.equalsIgnoreCase(t.strip())).findFirst()
                        .orElseThrow(() -> new IllegalArgumentException("not one of " + allowed)));
        spec.choices = allowed;
        return spec;
    }

    /**
     * One constant of an enum, written in lower case in the file ({@code left_front} for {@code LEFT_FRONT};
     * any case is accepted).
     *
     * @param name     the parameter's name in the network file
     * @param constants the enum
     * @param <E>      the enum's type
     * @return a required declaration
     */
    public static <E extends Enum<E>> ParameterSpec<E> choice(String name, Class<E> constants) {
        List<String> allowed = Arrays.stream(constants.getEnumConstants()).map(c -> c.name().toLowerCase(Locale.ROOT))
                .toList();
        ParameterSpec<E> spec = new ParameterSpec<>(name, ParameterType.STRING, "one of " + String.join(", ", allowed),
                t -> Enum.valueOf(constants, t.strip().toUpperCase(Locale.ROOT)));
        spec.choices = allowed;
        return spec;
    }

    /**
     * Text that {@code parser} turns into a value (an expression, a list of names); what the parser refuses with an
     * {@link IllegalArgumentException} is refused as a bad value of this parameter, with the parser's message.
     *
     * @param name     the parameter's name in the network file
     * @param expected what a good value is, to follow "must be" (e.g. {@code "an expression over the inputs"})
     * @param parser   makes the value from the text, or throws {@link IllegalArgumentException}
     * @param <V>      the value's type
     * @return a required declaration
     */
    public static <V> ParameterSpec<V> parsed(String name, String expected, Function<String, V> parser) {
        ParameterSpec<V> spec = new ParameterSpec<>(name, ParameterType.STRING, expected, parser);
        spec.tellsParserMessage = true;
        return spec;
    }

    /**
     * The unit of a number, written after it in messages and lists ({@code m}, {@code rad/s}; {@code 1}, for a ratio
     * or a gain, is not written).
     *
     * @param symbol the unit
     * @return a new declaration
     */
    public ParameterSpec<T> unit(String symbol) {
        ParameterSpec<T> c = copy();
        c.unit = symbol == null ? "" : symbol;
        return c;
    }

    /**
     * Allows numbers from {@code min} to {@code max}, both included.
     *
     * @param min the smallest number allowed
     * @param max the largest number allowed
     * @return a new declaration
     */
    public ParameterSpec<T> range(double min, double max) {
        return ranged(ValueRange.closed(min, max));
    }

    /**
     * Allows numbers from {@code min} up, {@code min} included.
     *
     * @param min the smallest number allowed
     * @return a new declaration
     */
    public ParameterSpec<T> atLeast(double min) {
        return ranged(range.withMin(min, true));
    }

    /**
     * Allows numbers above {@code min}, {@code min} excluded.
     *
     * @param min the bound, itself not allowed
     * @return a new declaration
     */
    public ParameterSpec<T> above(double min) {
        return ranged(range.withMin(min, false));
    }

    /**
     * Allows numbers up to {@code max}, {@code max} included.
     *
     * @param max the largest number allowed
     * @return a new declaration
     */
    public ParameterSpec<T> atMost(double max) {
        return ranged(range.withMax(max, true));
    }

    /**
     * Allows numbers below {@code max}, {@code max} excluded.
     *
     * @param max the bound, itself not allowed
     * @return a new declaration
     */
    public ParameterSpec<T> below(double max) {
        return ranged(range.withMax(max, false));
    }

    private ParameterSpec<T> ranged(ValueRange r) {
        if (fileType != ParameterType.DOUBLE && fileType != ParameterType.LONG && fileType != ParameterType.DOUBLES) {
            throw new IllegalStateException("parameter '" + name + "' is " + expected + ": only numbers have a range");
        }
        ParameterSpec<T> c = copy();
        c.range = r;
        return c;
    }

    /**
     * Allows one value outside the range too: the "off" of a setting ({@code range(1, 1000).or(0.0)}).
     *
     * @param value the value also allowed
     * @return a new declaration
     */
    public ParameterSpec<T> or(T value) {
        ParameterSpec<T> c = copy();
        c.alsoAllowed = value;
        return c;
    }

    /**
     * The value {@link #read} returns when the file does not give the parameter.
     *
     * @param value the default (it must lie in the range)
     * @return a new declaration
     */
    public ParameterSpec<T> defaultValue(T value) {
        ParameterSpec<T> c = copy();
        c.defaultValue = value;
        c.defaultText = printed(value);
        c.defaultIsValue = value != null;
        c.optional = true;
        return c;
    }

    /**
     * The parameter may be left out, and its default depends on something else (another parameter, the robot):
     * {@link #read} returns {@code null} and the node reads it with {@link #readOr}; {@code text} says what the
     * default is, for lists and the editor.
     *
     * @param text the default in words (e.g. {@code "the standing height"})
     * @return a new declaration
     */
    public ParameterSpec<T> defaultDescribed(String text) {
        ParameterSpec<T> c = copy();
        c.defaultValue = null;
        c.defaultText = text;
        c.defaultIsValue = false;
        c.optional = true;
        return c;
    }

    /**
     * A node must give the parameter: undoes a default (of a declaration narrowed from another one).
     *
     * @return a new declaration
     */
    public ParameterSpec<T> required() {
        ParameterSpec<T> c = copy();
        c.defaultValue = null;
        c.defaultText = null;
        c.defaultIsValue = false;
        c.optional = false;
        return c;
    }

    /**
     * The parameter may be left out, and then has no value: {@link #read} returns {@code null}.
     *
     * @return a new declaration
     */
    public ParameterSpec<T> optional() {
        ParameterSpec<T> c = copy();
        c.optional = true;
        return c;
    }

    /**
     * What the parameter does, in one sentence, for {@code fdnet info --params} and the editor.
     *
     * @param text the description
     * @return a new declaration
     */
    public ParameterSpec<T> describe(String text) {
        ParameterSpec<T> c = copy();
        c.description = text == null ? "" : text;
        return c;
    }

    /**
     * The parameter may change while the network runs: a change makes a fresh instance of the node with the new
     * value. Without it, a running network refuses the change (the file and a restart are the way).
     *
     * @return a new declaration
     */
    public ParameterSpec<T> live() {
        ParameterSpec<T> c = copy();
        c.live = true;
        return c;
    }

    /**
     * The node's value of this parameter, checked: the default when the file does not give it ({@code null} for an
     * optional parameter without default).
     *
     * @param parameters the node's parameters, as {@code init} receives them
     * @return the value
     * @throws ParameterException naming module, node, parameter and what it must be, when the parameter is
     *                            required and missing, does not parse, or lies outside the range
     */
    public T read(NodeParameters parameters) {
        String text = parameters.text(name);
        if (text == null) {
            if (!optional) {
                throw parameters.problem(name, "is required: it must be " + requirement());
            }
            return defaultValue;
        }
        return valueOf(parameters.node(), text);
    }

    /**
     * The node's value of this parameter, checked, or {@code fallback} when the file does not give it: for a default
     * that depends on something else ({@link #defaultDescribed}).
     *
     * @param parameters the node's parameters
     * @param fallback   the value when the parameter is absent
     * @return the value
     * @throws ParameterException as {@link #read} does
     */
    public T readOr(NodeParameters parameters, T fallback) {
        String text = parameters.text(name);
        return text == null ? fallback : valueOf(parameters.node(), text);
    }

    /**
     * Whether the file gives this parameter.
     *
     * @param parameters the node's parameters
     * @return true when it is present
     */
    public boolean isGiven(NodeParameters parameters) {
        return parameters.has(name);
    }

    /**
     * The value of {@code text}, checked as {@link #read} checks it.
     *
     * @param node the node the text belongs to (named in a refusal)
     * @param text the parameter's text
     * @return the value
     * @throws ParameterException when the text does not parse or lies outside the range
     */
    public T valueOf(NodeRef node, String text) {
        T value;
        try {
            value = parser.apply(text);
        } catch (IllegalArgumentException e) {
            String why = tellsParserMessage && e.getMessage() != null ? ": " + e.getMessage() : "";
            throw new ParameterException(node.spelledOut() + ": parameter '" + name + "' must be " + requirement()
                    + ", was '" + text.strip() + "'" + why, e);
        }
        if (!allowed(value)) {
            throw new ParameterException(node.spelledOut() + ": parameter '" + name + "' must be " + requirement()
                    + ", was " + printed(value));
        }
        return value;
    }

    private boolean allowed(T value) {
        if (alsoAllowed != null && alsoAllowed.equals(value)) {
            return true;
        }
        if (value instanceof Number n) {
            return range.contains(n.doubleValue());
        }
        if (value instanceof double[] all) {
            return Arrays.stream(all).allMatch(range::contains);
        }
        return true;
    }

    /**
     * What a good value is, to follow "must be": {@code a number in [0, 0.3] m}, {@code a whole number, at least 1},
     * {@code 0 or a number in [1, 1000] s}, {@code one of sine, square}.
     *
     * @return the requirement in words
     */
    public String requirement() {
        String off = alsoAllowed == null ? "" : printed(alsoAllowed) + " or ";
        String shown = unit.equals(DIMENSIONLESS) ? "" : unit;
        if (!range.isBounded()) {
            return off + expected + (shown.isEmpty() ? "" : " (" + shown + ")");
        }
        String each = fileType == ParameterType.DOUBLES ? ", each " : " ";
        return off + expected + each + range.phrase(shown);
    }

    private String printed(T value) {
        if (value instanceof Double d) {
            return ValueRange.format(d);
        }
        if (value instanceof double[] all) {
            return String.join(", ", Arrays.stream(all).mapToObj(ValueRange::format).toList());
        }
        if (value instanceof Enum<?> e) {
            return e.name().toLowerCase(Locale.ROOT);
        }
        return String.valueOf(value);
    }

    /**
     * The parameter's name in the network file.
     *
     * @return the name
     */
    public String name() {
        return name;
    }

    /**
     * The {@code type} attribute the editor writes when it adds this parameter to a node.
     *
     * @return the file type ({@link ParameterType#STRING} for text, choices and parsed values)
     */
    public ParameterType fileType() {
        return fileType;
    }

    /**
     * The unit ("" for none).
     *
     * @return the unit
     */
    public String unit() {
        return unit;
    }

    /**
     * The numbers allowed ({@link ValueRange#ANY} when the declaration sets no range).
     *
     * @return the range
     */
    public ValueRange range() {
        return range;
    }

    /**
     * The words allowed, for a {@link #choice} (empty otherwise).
     *
     * @return the choices
     */
    public List<String> choices() {
        return choices;
    }

    /**
     * The default as text: the value, or the words of {@link #defaultDescribed}; {@code null} when the parameter is
     * required or has no default.
     *
     * @return the default's text
     */
    public String defaultText() {
        return defaultText;
    }

    /**
     * Whether {@link #defaultText()} is a value a file could give (from {@link #defaultValue(Object)}), rather than
     * words ({@link #defaultDescribed}).
     *
     * @return true for a default value
     */
    public boolean hasDefaultValue() {
        return defaultIsValue;
    }

    /**
     * Whether a node must give this parameter.
     *
     * @return true when it has no default and is not optional
     */
    public boolean isRequired() {
        return !optional;
    }

    /**
     * What the parameter does.
     *
     * @return the description ("" when none was given)
     */
    public String description() {
        return description;
    }

    /**
     * Whether the parameter may change while the network runs.
     *
     * @return true when declared {@link #live()}
     */
    public boolean isLive() {
        return live;
    }

    @Override
    public String toString() {
        return name + ": " + requirement() + (defaultText == null ? optional ? ", optional" : ", required"
                : ", default " + defaultText) + (live ? ", live" : "");
    }
}
