package org.fdnet.roq.node;

import org.fdnet.event.ValueType;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.SensorData;
import org.fdnet.runtime.Value;

/**
 * A sensor of RoQ in the network: parameter {@code channel} (required) names which — {@code joint_angles},
 * {@code joint_velocities}, {@code joint_torques}, {@code attitude}, {@code imu_gyro}, {@code imu_accel}, {@code foot_forces}, {@code foot_contacts},
 * {@code wheel_speeds}, {@code ir_range}, {@code ultrasonic_range}, {@code body_position},
 * {@code centre_of_mass}, {@code depth_image} (see {@link SensorChannel}); {@code every} (default 1) feeds one
 * simulator snapshot in that many. The {@link org.fdnet.roq.bridge.SimBridge} pushes the values, every sensor of
 * one snapshot in one commit, each stamped with the snapshot's tick.
 */
public class RoqSensor extends SensorData {
    private SensorChannel channel;
    private int every;
    private double[] buffer;

    @Override
    public ValueType type() {
        return ValueType.DOUBLES;
    }

    public static final ParameterSpec<SensorChannel> CHANNEL = ParameterSpec.choice("channel", SensorChannel.class)
            .describe("which of RoQ's sensors this Data holds");
    public static final ParameterSpec<Long> EVERY = ParameterSpec.whole("every").unit("snapshots").atLeast(1)
            .defaultValue(1L).describe("feed one simulator snapshot in this many");

    @Override
    protected void init(NodeParameters p) {
        channel = CHANNEL.read(p);
        every = EVERY.read(p).intValue();
        buffer = new double[channel.length()];
    }

    public SensorChannel channel() {
        return channel;
    }

    /**
     * Its reading of snapshot number {@code count}, stamped with the snapshot's tick ({@link Value#tick()}), when
     * that snapshot is one of this sensor's (one in {@code every}); else null. The bridge pushes the readings of
     * all sensors of one snapshot together.
     */
    public Value reading(SensorSnapshot snapshot, long count) {
        if (count % every != 0) {
            return null;
        }
        channel.read(snapshot, buffer);
        return Value.ofDoubles(buffer).withTick(snapshot.tick());
    }
}
