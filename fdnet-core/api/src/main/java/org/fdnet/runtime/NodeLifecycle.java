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

    public static void init(Data data, NodeParameters parameters) throws Exception {
        data.init(parameters);
    }

    public static Value initialValue(Data data, NodeParameters parameters) {
        return data.initialValue(parameters);
    }

    public static Value accept(Data data, Value proposed) {
        return data.accept(proposed);
    }

    public static void close(Data data) {
        data.close();
    }

    /** Makes {@code port} the Data's way to the engine ({@code null} when it leaves). */
    public static void bind(Data data, Data.DataPort port) {
        data.bind(port);
    }

    public static void start(SensorData sensor) {
        sensor.start();
    }

    public static void stop(SensorData sensor) {
        sensor.stop();
    }

    public static void init(Relation relation, NodeParameters parameters) throws Exception {
        relation.init(parameters);
    }

    public static void compute(Relation relation, RelationContext context) throws Exception {
        relation.compute(context);
    }

    public static void close(Relation relation) {
        relation.close();
    }
}
