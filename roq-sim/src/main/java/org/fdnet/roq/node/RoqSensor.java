package org.fdnet.roq.node;

import java.util.Arrays;
import java.util.Locale;
import org.fdnet.event.ValueType;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.SensorData;
import org.fdnet.runtime.Value;

/**
 * A sensor of RoQ in the network: parameter {@code channel} (required) names which — {@code joint_angles},
 * {@code joint_velocities}, {@code joint_torques}, {@code attitude}, {@code imu_gyro}, {@code imu_accel}, {@code foot_forces}, {@code foot_contacts},
 * {@code wheel_speeds}, {@code ir_range}, {@code ultrasonic_range}, {@code body_position},
 * {@code centre_of_mass}, {@code depth_image} (see {@link SensorChannel}); {@code every} (default 1) feeds one
 * simulator snapshot in that many. The {@link org.fdnet.roq.bridge.SimBridge} pushes the values.
 */
public class RoqSensor extends SensorData {
    private SensorChannel channel;
    private int every;
    private double[] buffer;

    @Override
    public ValueType type() {
        return ValueType.DOUBLES;
    }

    @Override
    protected void init(NodeParameters p) {
        String name = p.requireString("channel").strip();
        try {
            channel = SensorChannel.valueOf(name.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw p.invalid("channel", "must be one of " + Arrays.toString(SensorChannel.values()).toLowerCase(Locale.ROOT)
                    + ", was '" + name + "'");
        }
        long e = p.longValue("every", 1);
        if (e < 1) {
            throw p.invalid("every", "must be at least 1 (feed one snapshot in that many), was " + e);
        }
        every = (int) e;
        buffer = new double[channel.length()];
    }

    public SensorChannel channel() {
        return channel;
    }

    /** Feeds snapshot number {@code count} when it is one of this sensor's (one in {@code every}). */
    public void feed(SensorSnapshot snapshot, long count) {
        if (count % every != 0) {
            return;
        }
        channel.read(snapshot, buffer);
        push(Value.ofDoubles(buffer));
    }
}
