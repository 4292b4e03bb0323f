package org.fdnet.runtime;

import java.util.List;
import org.fdnet.netinfo.NodeRef;

/**
 * What a Relation sees during one firing. Inputs are the Datas it reads, in the order its Reader
 * connections are declared; outputs the Datas it writes, in Writer order. A name may be the Data's node
 * name or its full {@code Module/Node}. An input whose Data is not in the running network (its module is
 * not loaded, or it lives on a host that does not feed it) reads as {@code null}; writing to a missing
 * output is ignored. Touching a Data the Relation is not connected to is an IllegalArgumentException.
 *
 * <p>A firing that adds its inputs {@code a} and {@code b}, treating a missing one as 0, and writes the sum and
 * whether it is above the Relation's field {@code limit}:
 *
 * <pre>{@code
 * protected void compute(RelationContext context) {
 *     double sum = context.inputDouble(context.inputIndex("a"), 0) + context.inputDouble(context.inputIndex("b"), 0);
 *     context.output("sum", Value.of(sum));
 *     context.output("over", Value.of(sum > limit));   // both become visible together
 *     if (!context.missingInputs().isEmpty()) {
 *         context.report("missing " + context.missingInputs());
 *     }
 * }
 * }</pre>
 */
public interface RelationContext {
    /**
     * The Relation that is firing.
     *
     * @return its module and node name
     */
    NodeRef self();

    /**
     * The number of Reader connections, missing Datas included.
     *
     * @return the number of inputs; valid indexes are {@code 0} to this minus one
     */
    int inputCount();

    /**
     * The Data behind input {@code index}, as declared (also when it is missing).
     *
     * @param index the input's position in Reader order, from 0
     * @return the Data's module and node name
     */
    NodeRef inputRef(int index);

    /**
     * The snapshot value of input {@code index}, or {@code null} when that Data is missing.
     *
     * @param index the input's position in Reader order, from 0
     * @return the value as of this firing's snapshot, or null when the Data is not in the running network
     * @throws IllegalArgumentException when there is no input {@code index}
     */
    Value input(int index);

    /**
     * The snapshot value of the input called {@code name}.
     *
     * @param name the Data's node name, or its full {@code Module/Node}
     * @return the value as of this firing's snapshot, or null when the Data is not in the running network
     * @throws IllegalArgumentException when the Relation does not read a Data of that name
     */
    Value input(String name);

    /**
     * The input's value as a number, or {@code fallback} when it is missing.
     *
     * @param index    the input's position in Reader order, from 0
     * @param fallback what to return when the Data is not in the running network
     * @return the value as {@link Value#asDouble()} gives it, or {@code fallback}
     * @throws IllegalArgumentException when there is no input {@code index} or its value is not a number
     */
    default double inputDouble(int index, double fallback) {
        Value v = input(index);
        return v == null ? fallback : v.asDouble();
    }

    /**
     * Index of the input called {@code name}, or -1.
     *
     * @param name the Data's node name, or its full {@code Module/Node}
     * @return the input's position in Reader order, or -1 when the Relation does not read it
     */
    int inputIndex(String name);

    /**
     * Whether input {@code index} was written since the previous firing of this Relation.
     *
     * @param index the input's position in Reader order, from 0
     * @return true when its value is newer than the one the previous firing saw; false when it is missing
     * @throws IllegalArgumentException when there is no input {@code index}
     */
    boolean inputChanged(int index);

    /**
     * The number of Writer connections, missing Datas included.
     *
     * @return the number of outputs; valid indexes are {@code 0} to this minus one
     */
    int outputCount();

    /**
     * The Data behind output {@code index}, as declared (also when it is missing).
     *
     * @param index the output's position in Writer order, from 0
     * @return the Data's module and node name
     */
    NodeRef outputRef(int index);

    /**
     * Index of the output called {@code name}, or -1.
     *
     * @param name the Data's node name, or its full {@code Module/Node}
     * @return the output's position in Writer order, or -1 when the Relation does not write it
     */
    int outputIndex(String name);

    /**
     * Whether output {@code index} is in the running network.
     *
     * @param index the output's position in Writer order, from 0
     * @return false when its Data is missing (a write to it is then ignored)
     */
    boolean outputPresent(int index);

    /**
     * The output Data's current value (e.g. to integrate on it), or {@code null} when it is missing.
     *
     * @param index the output's position in Writer order, from 0
     * @return the Data's latest committed value (not what this firing wrote), or null when it is missing
     */
    Value outputValue(int index);

    /**
     * Writes output {@code index}; the value is committed with the firing's other writes when {@code compute}
     * returns normally. A second write to the same output in one firing replaces the first.
     *
     * @param index the output's position in Writer order, from 0
     * @param value the value, converted to the Data's type at commit; null takes back this firing's write
     * @throws IllegalArgumentException when there is no output {@code index}
     */
    void output(int index, Value value);

    /**
     * Writes the output called {@code name}, as {@link #output(int, Value)} does.
     *
     * @param name  the Data's node name, or its full {@code Module/Node}
     * @param value the value, converted to the Data's type at commit; null takes back this firing's write
     * @throws IllegalArgumentException when the Relation does not write a Data of that name
     */
    void output(String name, Value value);

    /**
     * Writes {@code value} to every output.
     *
     * @param value the value each output gets, converted to each Data's type at commit
     */
    default void outputAll(Value value) {
        for (int i = 0; i < outputCount(); i++) {
            output(i, value);
        }
    }

    /**
     * Time of this firing, µs since the epoch.
     *
     * @return the network clock's time, read once per firing (every call in one firing gives the same)
     */
    long now();

    /**
     * Seconds since the network started: a clock for waveforms and gaits.
     *
     * @return seconds since the start, on the network's clock (the driven clock in stepped runs)
     */
    double seconds();

    /**
     * Whether this firing comes from the Relation's period rather than from an input.
     *
     * @return true for a firing of the {@code period} timer, false for one caused by an input or by the start
     */
    boolean periodic();

    /**
     * Reports a status or value of the Relation (a RelationValueEvent) when it differs from the last one.
     *
     * @param status short text for the editor and the logger, e.g. {@code "waiting for ground"}; not null
     */
    void report(String status);

    /**
     * The network-wide API: find, describe, create, connect, follow, load (FDNet's Servants).
     *
     * @return the Servants acting for this Relation; ask again in each firing rather than keeping them
     */
    Servants servants();

    /**
     * The inputs declared but missing right now.
     *
     * @return a new list of the missing inputs' Datas, in Reader order; empty when every input is present
     */
    List<NodeRef> missingInputs();
}
