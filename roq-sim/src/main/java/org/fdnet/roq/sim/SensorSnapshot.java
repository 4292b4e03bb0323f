package org.fdnet.roq.sim;

import java.nio.ByteBuffer;

import static org.fdnet.roq.sim.SharedBlockLayout.*;

/**
 * One consistent set of the RoQ's sensor readings at one tick, owned by the caller and refilled in place by
 * {@link RoqSimulator#read(SensorSnapshot)} without allocating. Values a real RoQ senses: joint angles, velocities
 * and torques, inclinometer roll and pitch, IMU gyro and accelerometer, sole contact forces, infrared and ultrasonic ranges, a depth image.
 * Values it cannot sense are named {@code groundTruth…}: for tests and the view, not for controllers.
 */
public final class SensorSnapshot {
    private long tick;
    private double simTime;
    private final double[] jointAngle = new double[RoqGeometry.JOINTS];
    private final double[] jointVelocity = new double[RoqGeometry.JOINTS];
    private final double[] jointTorque = new double[RoqGeometry.JOINTS];
    private double roll;
    private double pitch;
    private final double[] footForce = new double[RoqGeometry.LEGS];
    private final double[] wheelSpeed = new double[RoqGeometry.LEGS];
    private double irRange;
    private double ultrasonicRange;
    private final double[] bodyPosition = new double[3];
    private final double[] bodyQuaternion = new double[4];
    private final double[] centreOfMass = new double[3];
    private int brokenCount;
    private final long[] brokenMask = new long[Course.MAX_FRAGILE_CELLS / 64];
    private long depthFrames;
    private final float[] depth = new float[RoqGeometry.DEPTH_WIDTH * RoqGeometry.DEPTH_HEIGHT];
    private final double[] gyro = new double[3];
    private final double[] accelerometer = new double[3];
    private final double[] pushForce = new double[3];

    /** Copies the snapshot region of the block; the caller holds the seqlock read. */
    void copyFrom(ByteBuffer b) {
        tick = b.getLong(S_TICK);
        simTime = b.getDouble(S_TIME);
        for (int j = 0; j < RoqGeometry.JOINTS; j++) {
            jointAngle[j] = b.getDouble(S_JOINT_ANGLE + 8 * j);
            jointVelocity[j] = b.getDouble(S_JOINT_VELOCITY + 8 * j);
            jointTorque[j] = b.getDouble(S_JOINT_TORQUE + 8 * j);
        }
        roll = b.getDouble(S_ROLL);
        pitch = b.getDouble(S_PITCH);
        for (int i = 0; i < RoqGeometry.LEGS; i++) {
            footForce[i] = b.getDouble(S_FOOT_FORCE + 8 * i);
            wheelSpeed[i] = b.getDouble(S_WHEEL_SPEED + 8 * i);
        }
        irRange = b.getDouble(S_IR_RANGE);
        ultrasonicRange = b.getDouble(S_ULTRASONIC_RANGE);
        for (int i = 0; i < 3; i++) {
            bodyPosition[i] = b.getDouble(S_BODY_POSITION + 8 * i);
            centreOfMass[i] = b.getDouble(S_CENTRE_OF_MASS + 8 * i);
        }
        for (int i = 0; i < 4; i++) {
            bodyQuaternion[i] = b.getDouble(S_BODY_QUATERNION + 8 * i);
        }
        brokenCount = (int) b.getLong(S_BROKEN_COUNT);
        for (int i = 0; i < brokenMask.length; i++) {
            brokenMask[i] = b.getLong(S_BROKEN_MASK + 8 * i);
        }
        depthFrames = b.getLong(S_DEPTH_FRAMES);
        for (int i = 0; i < depth.length; i++) {
            depth[i] = b.getFloat(S_DEPTH + 4 * i);
        }
        for (int i = 0; i < 3; i++) {
            gyro[i] = b.getDouble(S_GYRO + 8 * i);
            accelerometer[i] = b.getDouble(S_ACCEL + 8 * i);
            pushForce[i] = b.getDouble(S_PUSH_FORCE + 8 * i);
        }
    }

    /** Copies every value of {@code other} into this snapshot. */
    public void copyFrom(SensorSnapshot other) {
        tick = other.tick;
        simTime = other.simTime;
        System.arraycopy(other.jointAngle, 0, jointAngle, 0, jointAngle.length);
        System.arraycopy(other.jointVelocity, 0, jointVelocity, 0, jointVelocity.length);
        System.arraycopy(other.jointTorque, 0, jointTorque, 0, jointTorque.length);
        roll = other.roll;
        pitch = other.pitch;
        System.arraycopy(other.footForce, 0, footForce, 0, footForce.length);
        System.arraycopy(other.wheelSpeed, 0, wheelSpeed, 0, wheelSpeed.length);
        irRange = other.irRange;
        ultrasonicRange = other.ultrasonicRange;
        System.arraycopy(other.bodyPosition, 0, bodyPosition, 0, 3);
        System.arraycopy(other.bodyQuaternion, 0, bodyQuaternion, 0, 4);
        System.arraycopy(other.centreOfMass, 0, centreOfMass, 0, 3);
        brokenCount = other.brokenCount;
        System.arraycopy(other.brokenMask, 0, brokenMask, 0, brokenMask.length);
        depthFrames = other.depthFrames;
        System.arraycopy(other.depth, 0, depth, 0, depth.length);
        System.arraycopy(other.gyro, 0, gyro, 0, 3);
        System.arraycopy(other.accelerometer, 0, accelerometer, 0, 3);
        System.arraycopy(other.pushForce, 0, pushForce, 0, 3);
    }

    /** The loop's tick number (0 before the first tick). */
    public long tick() {
        return tick;
    }

    /** Simulated time, s (tick × 1 ms). */
    public double simTime() {
        return simTime;
    }

    /** Angle of joint {@code j} ({@link RoqGeometry#jointIndex}), rad. */
    public double jointAngle(int j) {
        return jointAngle[j];
    }

    /** Velocity of joint {@code j}, rad/s. */
    public double jointVelocity(int j) {
        return jointVelocity[j];
    }

    /** Torque the motor applies at joint {@code j} (after its limits), N·m. */
    public double jointTorque(int j) {
        return jointTorque[j];
    }

    /** Copies the 12 joint angles into {@code into}. */
    public void copyJointAngles(double[] into) {
        System.arraycopy(jointAngle, 0, into, 0, RoqGeometry.JOINTS);
    }

    /** Inclinometer roll (about the body's x axis, positive = left side up), rad. */
    public double roll() {
        return roll;
    }

    /** Inclinometer pitch (about the body's y axis, positive = nose down), rad. */
    public double pitch() {
        return pitch;
    }

    /** Normal force on leg {@code leg}'s sole (tactile sensor), N. */
    public double footForce(int leg) {
        return footForce[leg];
    }

    /** Whether leg {@code leg}'s sole touches something (force above 1 N). */
    public boolean footContact(int leg) {
        return footForce[leg] > 1.0;
    }

    /** Speed of leg {@code leg}'s wheel, rad/s. */
    public double wheelSpeed(int leg) {
        return wheelSpeed[leg];
    }

    /** Infrared range ahead and down, m ({@link RoqGeometry#IR_MAX_RANGE} when nothing is in range). */
    public double irRange() {
        return irRange;
    }

    /** Ultrasonic range ahead, m ({@link RoqGeometry#ULTRASONIC_MAX_RANGE} when nothing is in range). */
    public double ultrasonicRange() {
        return ultrasonicRange;
    }

    /** Depth at pixel (x, y) of the camera image (x to the right, y down), m. */
    public float depth(int x, int y) {
        return depth[y * RoqGeometry.DEPTH_WIDTH + x];
    }

    /** How many complete depth images the camera has produced (a row every {@link RoqGeometry#DEPTH_ROW_PERIOD_TICKS} ticks). */
    public long depthFrames() {
        return depthFrames;
    }

    /**
     * IMU gyro: the body's angular rate about its own x (roll), y (pitch) and z (yaw) axes, component {@code i},
     * rad/s (with noise ±5 mrad/s and a fixed bias up to ±10 mrad/s per axis when sensor noise is on).
     */
    public double gyro(int i) {
        return gyro[i];
    }

    /**
     * IMU accelerometer: specific force along the body's axes, component {@code i}, m/s² (standing level it reads
     * about +9.81 on z; noise ±0.05 and a fixed bias up to ±0.1 m/s² per axis when sensor noise is on).
     */
    public double accelerometer(int i) {
        return accelerometer[i];
    }

    /** Ground truth: the external push ({@link Push}) acting on the body during this tick, world frame, N. */
    public double groundTruthPushForce(int i) {
        return pushForce[i];
    }

    /** Ground truth, not sensed: the body centre's position in the course frame, component {@code i}, m. */
    public double groundTruthBodyPosition(int i) {
        return bodyPosition[i];
    }

    /** Ground truth: the body's orientation quaternion (w, x, y, z), component {@code i}. */
    public double groundTruthBodyQuaternion(int i) {
        return bodyQuaternion[i];
    }

    /**
     * Ground truth: the body-frame point {@code body} (x, y, z) in the course frame, into {@code world} (3 numbers), m.
     * For measuring and drawing, never for control.
     */
    public void groundTruthToWorld(double[] body, double[] world) {
        double w = bodyQuaternion[0];
        double x = bodyQuaternion[1];
        double y = bodyQuaternion[2];
        double z = bodyQuaternion[3];
        double bx = body[0];
        double by = body[1];
        double bz = body[2];
        world[0] = bodyPosition[0] + (1 - 2 * (y * y + z * z)) * bx + 2 * (x * y - w * z) * by + 2 * (x * z + w * y) * bz;
        world[1] = bodyPosition[1] + 2 * (x * y + w * z) * bx + (1 - 2 * (x * x + z * z)) * by + 2 * (y * z - w * x) * bz;
        world[2] = bodyPosition[2] + 2 * (x * z - w * y) * bx + 2 * (y * z + w * x) * by + (1 - 2 * (x * x + y * y)) * bz;
    }

    /** Ground truth: the whole robot's centre of mass in the course frame, component {@code i}, m. */
    public double groundTruthCentreOfMass(int i) {
        return centreOfMass[i];
    }

    /** Ground truth: the body's heading (yaw about z), rad. */
    public double groundTruthYaw() {
        double w = bodyQuaternion[0];
        double x = bodyQuaternion[1];
        double y = bodyQuaternion[2];
        double z = bodyQuaternion[3];
        return Math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
    }

    /** How many fragile cells have broken. */
    public int brokenCellCount() {
        return brokenCount;
    }

    /** Whether fragile cell {@code index} (order of {@link Course#fragileCells()}) has broken. */
    public boolean isCellBroken(int index) {
        return (brokenMask[index >>> 6] & (1L << (index & 63))) != 0;
    }
}
