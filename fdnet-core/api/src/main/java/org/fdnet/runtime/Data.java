package org.fdnet.runtime;

import org.fdnet.event.ValueType;

/**
 * The base class of every Data node: a typed value and its timestamp. A subclass fixes the type and may
 * check or shape values ({@link #accept}); the engine stores the value, stamps it, tells the readers.
 *
 * <p>A subclass needs a public no-argument constructor. {@link #init} runs once, before the Data is
 * wired; the parameter {@code initial}, when present, is the first value (see {@link #initialValue}).
 * Methods are called by the engine only; a Data never holds a lock of its own and never blocks.
 *
 * <p>A Data holding a number that clamps every write into {@code [min, max]}, its two parameters declared once
 * ({@link ParameterSpec}):
 *
 * <pre>{@code
 * public class Clamped extends Data {
 *     public static final ParameterSpec<Double> MIN = ParameterSpec.number("min").describe("the lowest value kept");
 *     public static final ParameterSpec<Double> MAX = ParameterSpec.number("max").describe("the highest value kept");
 *
 *     private double min;
 *     private double max;
 *
 *     @Override
 *     public ValueType type() {
 *         return ValueType.DOUBLE;
 *     }
 *
 *     @Override
 *     protected void init(NodeParameters parameters) {
 *         min = MIN.read(parameters);
 *         max = MAX.read(parameters);
 *         if (min > max) {
 *             throw parameters.conflict(MIN, MAX, "min must not be above max");
 *         }
 *     }
 *
 *     @Override
 *     protected Value accept(Value proposed) {   // already a DOUBLE value
 *         return Value.of(Math.max(min, Math.min(max, proposed.asDouble())));
 *     }
 * }
 * }</pre>
 */
public abstract class Data {
    /** The first value, before anyone writes: read by {@link #initialValue} for every Data. */
    public static final ParameterSpec<String> INITIAL = ParameterSpec.text("initial").defaultDescribed("the type's zero")
            .describe("the first value, before anyone writes, in the Data's type");

    private volatile DataPort port;

    /**
     * The type of every value this Data holds; written values are converted to it before {@link #accept}.
     *
     * @return the same type on every call
     */
    public abstract ValueType type();

    /**
     * Reads parameters, once, before the Data is wired, each with its declaration ({@link ParameterSpec#read}); the
     * engine has already checked every declared one. Throw {@link ParameterException}
     * ({@link NodeParameters#conflict}) when two disagree.
     *
     * @param parameters the node's parameters as the network file gives them
     * @throws Exception when the node cannot start: the start, module load or change that would make it is
     *                   refused, with this message after the node's name, and the network stays as it was
     */
    protected void init(NodeParameters parameters) throws Exception {
    }

    /**
     * The value before anyone writes: parameter {@code initial} when given, else the type's zero.
     *
     * @param parameters the node's parameters
     * @return the first value, not yet stamped (the engine converts it to {@link #type()} and stamps it)
     * @throws ParameterException when {@code initial} is not a value of {@link #type()}
     */
    protected Value initialValue(NodeParameters parameters) {
        String initial = INITIAL.read(parameters);
        if (initial == null) {
            return Value.zero(type());
        }
        try {
            return Value.parse(type(), initial);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(parameters.node().spelledOut() + ": parameter 'initial' must be a "
                    + type().name().toLowerCase(java.util.Locale.ROOT) + " value, was '" + initial.strip() + "'", e);
        }
    }

    /**
     * Checks or shapes a value about to be written (already converted to {@link #type()}): return it, a
     * corrected value (e.g. clamped), or throw IllegalArgumentException to refuse it. Called on the
     * writer's thread, outside any lock; must be fast and free of side effects.
     *
     * @param proposed the value about to be written, never null
     * @return the value to store: {@code proposed} itself or a replacement of the same {@link #type()}, never null
     * @throws IllegalArgumentException to refuse the write, saying why (the writing Relation's firing fails)
     */
    protected Value accept(Value proposed) {
        return proposed;
    }

    /** Called when the Data leaves the running network (module unloaded, node destroyed, network stopped). */
    protected void close() {
    }

    /**
     * The current value (the engine's, always the latest committed one).
     *
     * @return the latest committed value (the last one, once the Data has left the network), or null before it first
     *         joins a running network
     */
    public final Value value() {
        DataPort p = port;
        return p == null ? null : p.current();
    }

    /**
     * Writes a value from outside the dataflow (a sensor, a device); see {@link SensorData}.
     *
     * @param value the value, converted to {@link #type()} and passed through {@link #accept}; not null
     * @throws IllegalStateException when this Data never joined a running network (once it has left, values are
     *                               ignored)
     * @throws IllegalArgumentException when the value cannot be converted or {@link #accept} refuses it
     */
    protected final void publish(Value value) {
        DataPort p = port;
        if (p == null) {
            throw new IllegalStateException(getClass().getSimpleName() + " is not part of a running network");
        }
        p.publish(value);
    }

    /** The engine's side of this Data while it is in a running network, else null. */
    final DataPort port() {
        return port;
    }

    final void bind(DataPort newPort) {
        this.port = newPort;
    }

    /**
     * What a Data sees of the engine: its current value and a way in for outside values. The engine implements it
     * ({@code org.fdnet.runtime.engine}); node authors never do.
     */
    public interface DataPort {
        /**
         * The Data's value as last committed.
         *
         * @return the latest committed value
         */
        Value current();

        /**
         * Converts, checks, stamps and stores a value from outside a firing, then tells the readers; ignored once the
         * Data has left the network.
         *
         * @param value the value to write, not null
         */
        void publish(Value value);

        /**
         * Publishes {@code values[i]} into {@code ports[i]} in one commit, as {@link SensorData#pushTogether}
         * documents (null ports and values, and ports of Datas no longer running, are left out).
         *
         * @param ports  the Datas to write, parallel to {@code values}
         * @param values the values to write; cleared when this returns
         */
        void publishTogether(DataPort[] ports, Value[] values);
    }
}
