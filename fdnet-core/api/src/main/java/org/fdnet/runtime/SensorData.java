package org.fdnet.runtime;

/**
 * A Data fed from outside the network: a device driver, a simulator, a test, or a distribution layer
 * mirroring a remote Data. Anyone holding the instance calls {@link #push}; the value enters the network
 * exactly as if a Relation had written it (stamped, logged, readers told). {@link #start} and
 * {@link #stop} frame the time the Data is part of a running network, e.g. to start a polling thread.
 *
 * <p>A thermometer polled ten times a second while the network runs ({@code readCelsius()} stands for the
 * device driver's call):
 *
 * <pre>{@code
 * public class Thermometer extends SensorData {
 *     private ScheduledExecutorService poller;
 *
 *     @Override
 *     public ValueType type() {
 *         return ValueType.DOUBLE;
 *     }
 *
 *     @Override
 *     protected void start() {
 *         poller = Executors.newSingleThreadScheduledExecutor();
 *         poller.scheduleAtFixedRate(() -> push(Value.of(readCelsius())), 0, 100, TimeUnit.MILLISECONDS);
 *     }
 *
 *     @Override
 *     protected void stop() {
 *         poller.shutdownNow();
 *     }
 * }
 * }</pre>
 */
public abstract class SensorData extends Data {
    /**
     * Puts a value into the running network. Thread-safe; runs the readers on the caller's thread when it can.
     *
     * @param value the new value, converted to {@link #type()} and passed through {@link #accept}; not null. To
     *              say which sensor snapshot it comes from, push {@code value.withTick(n)}
     * @throws IllegalStateException when this Data never joined a running network (once it has left, values are
     *                               ignored)
     * @throws IllegalArgumentException when the value cannot be converted or {@link #accept} refuses it
     */
    public final void push(Value value) {
        publish(value);
    }

    /**
     * Puts {@code values[i]} into {@code sensors[i]}, all in one commit: a Relation that reads several of them sees
     * all the new values or none (e.g. every reading of one sensor snapshot). A null sensor or value, or a sensor
     * not in a running network, is left out. The sensors must belong to the same network. {@code values} is
     * cleared. Thread-safe; runs the readers on the caller's thread when it can.
     *
     * @param sensors the Datas to write, parallel to {@code values}; null entries are skipped
     * @param values  the values to write, as long as {@code sensors}; null entries are skipped
     * @throws IllegalArgumentException when the sensors belong to different networks, or a value does not fit
     *                                  (nothing is written then)
     */
    public static void pushTogether(SensorData[] sensors, Value[] values) {
        DataPort[] ports = new DataPort[sensors.length];
        DataPort any = null;
        for (int i = 0; i < sensors.length; i++) {
            if (sensors[i] != null && sensors[i].port() != null) {
                ports[i] = sensors[i].port();
                any = ports[i];
            }
        }
        if (any != null) {
            any.publishTogether(ports, values);
        } else {
            java.util.Arrays.fill(values, null);
        }
    }

    /** The Data is wired and may push. */
    protected void start() {
    }

    /** The Data is leaving the network: stop pushing (pushes after this are ignored). */
    protected void stop() {
    }
}
