package org.fdnet.runtime.library;

import org.fdnet.event.ValueType;
import org.fdnet.runtime.SensorData;
import org.fdnet.runtime.Value;

/** A posture (vector of doubles) fed from outside, e.g. joint encoders. Parameter: {@code initial}. */
public class PostureSensor extends SensorData {
    @Override
    public ValueType type() {
        return ValueType.DOUBLES;
    }

    public void push(double... posture) {
        push(Value.ofDoubles(posture));
    }
}
