package org.fdnet.roq.node;

import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.SensorSnapshot;

/** One of RoQ's sensors as the network sees it: a vector of doubles read from a simulator snapshot. */
public enum SensorChannel {
    /** The 12 joint angles, rad (leg-major: fl, fr, hl, hr × yaw, lift, knee). */
    JOINT_ANGLES(RoqGeometry.JOINTS),
    /** The 12 joint velocities, rad/s. */
    JOINT_VELOCITIES(RoqGeometry.JOINTS),
    /** The 12 joint torques, N·m. */
    JOINT_TORQUES(RoqGeometry.JOINTS),
    /** The inclinometer: roll and pitch, rad. */
    ATTITUDE(2),
    /** The IMU's gyro: body angular rate about x (roll), y (pitch), z (yaw), rad/s. */
    IMU_GYRO(3),
    /** The IMU's accelerometer: specific force along the body's x, y, z, m/s² (+9.81 on z standing level). */
    IMU_ACCEL(3),
    /** The 4 foot force sensors, N. */
    FOOT_FORCES(RoqGeometry.LEGS),
    /** The 4 foot contact switches, 1 or 0. */
    FOOT_CONTACTS(RoqGeometry.LEGS),
    /** The 4 wheel encoders, rad/s. */
    WHEEL_SPEEDS(RoqGeometry.LEGS),
    /** The infrared range finder, m. */
    IR_RANGE(1),
    /** The ultrasonic range finder, m. */
    ULTRASONIC_RANGE(1),
    /** The body's position {x, y, z} in the world, m (the simulator's ground truth: odometry stands in for it). */
    BODY_POSITION(3),
    /** The centre of mass {x, y, z} in the world, m (ground truth). */
    CENTRE_OF_MASS(3),
    /** The depth camera's image, row by row, m. */
    DEPTH_IMAGE(RoqGeometry.DEPTH_WIDTH * RoqGeometry.DEPTH_HEIGHT);

    private final int length;

    SensorChannel(int length) {
        this.length = length;
    }

    public int length() {
        return length;
    }

    /** Copies this channel out of {@code s} into {@code into} (length {@link #length()}). */
    public void read(SensorSnapshot s, double[] into) {
        switch (this) {
            case JOINT_ANGLES -> s.copyJointAngles(into);
            case JOINT_VELOCITIES -> {
                for (int j = 0; j < length; j++) {
                    into[j] = s.jointVelocity(j);
                }
            }
            case JOINT_TORQUES -> {
                for (int j = 0; j < length; j++) {
                    into[j] = s.jointTorque(j);
                }
            }
            case ATTITUDE -> {
                into[0] = s.roll();
                into[1] = s.pitch();
            }
            case IMU_GYRO -> {
                for (int i = 0; i < 3; i++) {
                    into[i] = s.gyro(i);
                }
            }
            case IMU_ACCEL -> {
                for (int i = 0; i < 3; i++) {
                    into[i] = s.accelerometer(i);
                }
            }
            case FOOT_FORCES -> {
                for (int i = 0; i < length; i++) {
                    into[i] = s.footForce(i);
                }
            }
            case FOOT_CONTACTS -> {
                for (int i = 0; i < length; i++) {
                    into[i] = s.footContact(i) ? 1 : 0;
                }
            }
            case WHEEL_SPEEDS -> {
                for (int i = 0; i < length; i++) {
                    into[i] = s.wheelSpeed(i);
                }
            }
            case IR_RANGE -> into[0] = s.irRange();
            case ULTRASONIC_RANGE -> into[0] = s.ultrasonicRange();
            case BODY_POSITION -> {
                for (int i = 0; i < 3; i++) {
                    into[i] = s.groundTruthBodyPosition(i);
                }
            }
            case CENTRE_OF_MASS -> {
                for (int i = 0; i < 3; i++) {
                    into[i] = s.groundTruthCentreOfMass(i);
                }
            }
            case DEPTH_IMAGE -> {
                for (int y = 0; y < RoqGeometry.DEPTH_HEIGHT; y++) {
                    for (int x = 0; x < RoqGeometry.DEPTH_WIDTH; x++) {
                        into[y * RoqGeometry.DEPTH_WIDTH + x] = s.depth(x, y);
                    }
                }
            }
            default -> throw new IllegalStateException("unknown channel " + this);
        }
    }
}
