package org.fdnet.runtime;

import org.fdnet.event.ValueType;

/**
 * The base class of every Data node: a typed value and its timestamp. A subclass fixes the type and may
 * check or shape values ({@link #accept}); the engine stores the value, stamps it, tells the readers.
 *
 * <p>A subclass needs a public no-argument constructor. {@link #init} runs once, before the Data is
 * wired; the parameter {@code initial}, when present, is the first value (see {@link #initialValue}).
 * Methods are called by the engine only; a Data never holds a lock of its own and never blocks.
 */
public abstract class Data {
    /** The first value, before anyone writes: read by {@link #initialValue} for every Data. */
    public static final ParameterSpec<String> INITIAL = ParameterSpec.text("initial").defaultDescribed("the type's zero")
            .describe("the first value, before anyone writes, in the Data's type");

    private volatile DataPort port;

    /**
     * The type of every value this Data holds.
     *
     * @return the type
     */
    public abstract ValueType type();

    /**
     * Reads parameters, each with its declaration ({@link ParameterSpec#read}); the engine has already checked
     * every declared one. Throw {@link ParameterException} ({@link NodeParameters#conflict}) when two disagree.
     *
     * @param parameters the node's parameters
     * @throws Exception when the node cannot start; the message is shown with the node's name
     */
    protected void init(NodeParameters parameters) throws Exception {
    }

    /** The value before anyone writes: parameter {@code initial} when given, else the type's zero. */
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
     */
    protected Value accept(Value proposed) {
        return proposed;
    }

    /** Called when the Data leaves the running network (module unloaded, node destroyed, network stopped). */
    protected void close() {
    }

    /** The current value (the engine's, always the latest committed one). */
    public final Value value() {
        DataPort p = port;
        return p == null ? null : p.current();
    }

    /** Writes a value from outside the dataflow (a sensor, a device); see {@link SensorData}. */
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
        Value current();

        void publish(Value value);

        /**
         * Publishes {@code values[i]} into {@code ports[i]} in one commit, as {@link SensorData#pushTogether}
         * documents (null ports and values, and ports of Datas no longer running, are left out).
         */
        void publishTogether(DataPort[] ports, Value[] values);
    }
}
