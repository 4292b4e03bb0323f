package org.fdnet.runtime;

/**
 * A Data fed from outside the network: a device driver, a simulator, a test, or a distribution layer
 * mirroring a remote Data. Anyone holding the instance calls {@link #push}; the value enters the network
 * exactly as if a Relation had written it (stamped, logged, readers told). {@link #start} and
 * {@link #stop} frame the time the Data is part of a running network, e.g. to start a polling thread.
 */
public abstract class SensorData extends Data {
    /** Puts a value into the running network. Thread-safe; runs the readers on the caller's thread when it can. */
    public final void push(Value value) {
        publish(value);
    }

    /** The Data is wired and may push. */
    protected void start() {
    }

    /** The Data is leaving the network: stop pushing (pushes after this are ignored). */
    protected void stop() {
    }
}
