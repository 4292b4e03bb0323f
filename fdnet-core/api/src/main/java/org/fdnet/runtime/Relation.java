package org.fdnet.runtime;

/**
 * The base class of every Relation node: a processing agent that reads the Datas it is connected to by
 * Readers and writes those it is connected to by Writers.
 *
 * <p>Life of an instance: public no-argument constructor → {@link #init} once with its parameters →
 * {@link #compute} once when it starts, then each time a Data it reads changes (not by its own write)
 * and/or every {@code period} ms when the node has a {@code period} parameter → {@link #close}. The
 * engine never runs one instance twice at a time, so a Relation keeps state in plain fields. An
 * exception from {@code compute} marks the Relation FAILED (its writes of that firing are dropped); a
 * parameter change or a module reload makes a fresh instance.
 *
 * <p>A Relation that scales its first input by the parameter {@code gain} and writes it to every output; it
 * declares the parameter once ({@link ParameterSpec}), and the engine checks it before {@code init}:
 *
 * <pre>{@code
 * public class Gain extends Relation {
 *     public static final ParameterSpec<Double> GAIN = ParameterSpec.number("gain").range(0, 10).defaultValue(1.0)
 *             .describe("the factor the input is multiplied by").live();
 *
 *     private double gain;
 *
 *     @Override
 *     protected void init(NodeParameters parameters) {
 *         gain = GAIN.read(parameters);
 *     }
 *
 *     @Override
 *     protected void compute(RelationContext context) {
 *         Value in = context.input(0);   // null while that Data is not in the running network
 *         if (in != null) {
 *             context.outputAll(Value.of(gain * in.asDouble()));
 *         }
 *     }
 * }
 * }</pre>
 */
public abstract class Relation {
    /** Fire every this many milliseconds; the engine reads it for every Relation. */
    public static final ParameterSpec<Long> PERIOD = ParameterSpec.whole("period").unit("ms").atLeast(0)
            .defaultValue(0L).describe("fire every this many milliseconds (0: never by time)").live();
    /** Fire when a Data it reads changes; the engine reads it for every Relation. */
    public static final ParameterSpec<Boolean> ON_INPUT = ParameterSpec.flag("onInput")
            .defaultDescribed("true without a period or with triggers, else false")
            .describe("fire when a Data it reads changes").live();
    /** Only these inputs fire it; the engine reads it for every Relation. */
    public static final ParameterSpec<String> TRIGGERS = ParameterSpec.text("triggers").optional()
            .describe("comma-separated names of the inputs whose changes fire it (the others are only read)").live();

    /**
     * Reads parameters, once, before the first firing, each with its declaration ({@link ParameterSpec#read}); the
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
     * One firing: read inputs from {@code context} (a consistent snapshot), write outputs to it (they
     * become visible together when this returns normally).
     *
     * @param context this firing's inputs, outputs, clock and the Servants; valid only until this returns
     * @throws Exception to fail the firing: its writes are dropped and the Relation is marked FAILED
     */
    protected abstract void compute(RelationContext context) throws Exception;

    /**
     * The instance leaves the network (failed, replaced, unloaded, destroyed, stopped). It may be called
     * while its last firing is still finishing on another thread: release resources, do not wait for it.
     */
    protected void close() {
    }
}
