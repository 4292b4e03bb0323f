package org.fdnet.runtime.library;

import org.fdnet.event.ValueType;
import org.fdnet.runtime.SensorData;
import org.fdnet.runtime.Value;

/**
 * A number fed from outside the network (a device, a simulator, a test): whoever holds the instance
 * calls {@link #push(double)}. Parameter: {@code initial} (default 0).
 */
public class DoubleSensor extends SensorData {
    @Override
    public ValueType type() {
        return ValueType.DOUBLE;
    }

    public void push(double value) {
        push(Value.of(value));
    }
}
