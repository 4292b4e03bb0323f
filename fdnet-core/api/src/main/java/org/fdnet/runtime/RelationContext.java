package org.fdnet.runtime;

import java.util.List;
import org.fdnet.netinfo.NodeRef;

/**
 * What a Relation sees during one firing. Inputs are the Datas it reads, in the order its Reader
 * connections are declared; outputs the Datas it writes, in Writer order. A name may be the Data's node
 * name or its full {@code Module/Node}. An input whose Data is not in the running network (its module is
 * not loaded, or it lives on a host that does not feed it) reads as {@code null}; writing to a missing
 * output is ignored. Touching a Data the Relation is not connected to is an IllegalArgumentException.
 */
public interface RelationContext {
    NodeRef self();

    int inputCount();

    /** The Data behind input {@code index}, as declared (also when it is missing). */
    NodeRef inputRef(int index);

    /** The snapshot value of input {@code index}, or {@code null} when that Data is missing. */
    Value input(int index);

    Value input(String name);

    /** The input's value as a number, or {@code fallback} when it is missing. */
    default double inputDouble(int index, double fallback) {
        Value v = input(index);
        return v == null ? fallback : v.asDouble();
    }

    /** Index of the input called {@code name}, or -1. */
    int inputIndex(String name);

    /** Whether input {@code index} was written since the previous firing of this Relation. */
    boolean inputChanged(int index);

    int outputCount();

    NodeRef outputRef(int index);

    /** Index of the output called {@code name}, or -1. */
    int outputIndex(String name);

    /** Whether output {@code index} is in the running network. */
    boolean outputPresent(int index);

    /** The output Data's current value (e.g. to integrate on it), or {@code null} when it is missing. */
    Value outputValue(int index);

    void output(int index, Value value);

    void output(String name, Value value);

    /** Writes {@code value} to every output. */
    default void outputAll(Value value) {
        for (int i = 0; i < outputCount(); i++) {
            output(i, value);
        }
    }

    /** Time of this firing, µs since the epoch. */
    long now();

    /** Seconds since the network started: a clock for waveforms and gaits. */
    double seconds();

    /** Whether this firing comes from the Relation's period rather than from an input. */
    boolean periodic();

    /** Reports a status or value of the Relation (a RelationValueEvent) when it differs from the last one. */
    void report(String status);

    /** The network-wide API: find, describe, create, connect, follow, load (FDNet's Servants). */
    Servants servants();

    /** The inputs declared but missing right now. */
    List<NodeRef> missingInputs();
}
