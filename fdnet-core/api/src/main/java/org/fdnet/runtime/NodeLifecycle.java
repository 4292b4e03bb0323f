package org.fdnet.runtime;

/**
 * The engine's way into a node author's instance: the protected life-cycle methods of {@link Data},
 * {@link SensorData} and {@link Relation}, and the binding of a Data to its {@link Data.DataPort}. It lets the
 * engine ({@code org.fdnet.runtime.engine}) live in a package of its own while authors still see only the
 * protected methods they override. Called by the engine only.
 */
public final class NodeLifecycle {
    private NodeLifecycle() {
    }

    /**
     * Calls {@link Data#init}.
     *
     * @param data       the new instance
     * @param parameters its parameters
     * @throws Exception what {@code init} throws
     */
    public static void init(Data data, NodeParameters parameters) throws Exception {
        data.init(parameters);
    }

    /**
     * Calls {@link Data#initialValue}.
     *
     * @param data       the instance
     * @param parameters its parameters
     * @return its first value
     */
    public static Value initialValue(Data data, NodeParameters parameters) {
        return data.initialValue(parameters);
    }

    /**
     * Calls {@link Data#accept}.
     *
     * @param data     the Data being written
     * @param proposed the value, already converted to the Data's type
     * @return the value to store
     */
    public static Value accept(Data data, Value proposed) {
        return data.accept(proposed);
    }

    /**
     * Calls {@link Data#close}.
     *
     * @param data the Data leaving the network
     */
    public static void close(Data data) {
        data.close();
    }

    /**
     * Makes {@code port} the Data's way to the engine ({@code null} when it leaves).
     *
     * @param data the Data
     * @param port the engine's side of it, or null when it leaves the running network
     */
    public static void bind(Data data, Data.DataPort port) {
        data.bind(port);
    }

    /**
     * Calls {@link SensorData#start}.
     *
     * @param sensor the sensor, now wired
     */
    public static void start(SensorData sensor) {
        sensor.start();
    }

    /**
     * Calls {@link SensorData#stop}.
     *
     * @param sensor the sensor leaving the network
     */
    public static void stop(SensorData sensor) {
        sensor.stop();
    }

    /**
     * Calls {@link Relation#init}.
     *
     * @param relation   the new instance
     * @param parameters its parameters
     * @throws Exception what {@code init} throws
     */
    public static void init(Relation relation, NodeParameters parameters) throws Exception {
        relation.init(parameters);
    }

    /**
     * Calls {@link Relation#compute}.
     *
     * @param relation the Relation firing
     * @param context  this firing's context
     * @throws Exception what {@code compute} throws
     */
    public static void compute(Relation relation, RelationContext context) throws Exception {
        relation.compute(context);
    }

    /**
     * Calls {@link Relation#close}.
     *
     * @param relation the Relation leaving the network
     */
    public static void close(Relation relation) {
        relation.close();
    }
}
