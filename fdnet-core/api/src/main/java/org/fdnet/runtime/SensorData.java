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

    /**
     * Puts {@code values[i]} into {@code sensors[i]}, all in one commit: a Relation that reads several of them sees
     * all the new values or none (e.g. every reading of one sensor snapshot). A null sensor or value, or a sensor
     * not in a running network, is left out. The sensors must belong to the same network. {@code values} is
     * cleared. Thread-safe; runs the readers on the caller's thread when it can.
     *
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
