package org.fdnet.roq.sim;

import static org.fdnet.roq.sim.RoqGeometry.*;

/**
 * The figures the C loop needs, as one {@code double[]} handed over at open; indices match the {@code P_*}
 * constants in {@code src/main/c/roq_layout.h}. Built from {@link RoqGeometry}, so C holds no figure of its own.
 */
final class NativeParameters {
    static final int KP = 0;
    static final int KD = 1;
    static final int TORQUE_CONSTANT = 2;
    static final int RESISTANCE = 3;
    static final int SUPPLY_VOLTAGE_INDEX = 4;
    static final int CURRENT_LIMIT_INDEX = 5;
    static final int GEAR = 6;
    static final int EFFICIENCY = 7;
    static final int WHEEL_KV_INDEX = 8;
    static final int WHEEL_TORQUE = 9;
    static final int WHEEL_SPEED = 10;
    static final int JOINT_MIN_0 = 11;   // 3 values
    static final int JOINT_MAX_0 = 14;   // 3 values
    static final int INITIAL_POSE_0 = 17; // 3 values
    static final int BREAK_HOLD_TICKS = 20;
    static final int IR_0 = 21;          // x y z pitchDown maxRange
    static final int US_0 = 26;          // x y z halfAngle maxRange
    static final int CAMERA_0 = 31;      // x y z pitchDown fovX fovY maxRange
    static final int NOISE = 38;         // 1 = on
    static final int NOISE_SEED = 39;
    static final int IR_PERIOD = 40;
    static final int US_PERIOD = 41;
    static final int DEPTH_ROW_PERIOD = 42;
    static final int RANGE_SENSORS = 43; // 1 = on
    static final int COUNT = 44;

    private NativeParameters() {
    }

    static double[] of(SimOptions options) {
        double[] p = new double[COUNT];
        p[KP] = SERVO_KP;
        p[KD] = SERVO_KD;
        p[TORQUE_CONSTANT] = MOTOR_TORQUE_CONSTANT;
        p[RESISTANCE] = MOTOR_RESISTANCE;
        p[SUPPLY_VOLTAGE_INDEX] = SUPPLY_VOLTAGE;
        p[CURRENT_LIMIT_INDEX] = CURRENT_LIMIT;
        p[GEAR] = GEAR_RATIO;
        p[EFFICIENCY] = GEAR_EFFICIENCY;
        p[WHEEL_KV_INDEX] = WHEEL_KV;
        p[WHEEL_TORQUE] = WHEEL_MAX_TORQUE;
        p[WHEEL_SPEED] = WHEEL_MAX_SPEED;
        for (int k = 0; k < JOINTS_PER_LEG; k++) {
            p[JOINT_MIN_0 + k] = JOINT_MIN[k];
            p[JOINT_MAX_0 + k] = JOINT_MAX[k];
            p[INITIAL_POSE_0 + k] = STANDING_POSE[k];
        }
        p[BREAK_HOLD_TICKS] = Math.round(FragileCell.BREAK_HOLD_SECONDS / TIMESTEP);
        put(p, IR_0, IR_POSITION[0], IR_POSITION[1], IR_POSITION[2], IR_PITCH_DOWN, IR_MAX_RANGE);
        put(p, US_0, ULTRASONIC_POSITION[0], ULTRASONIC_POSITION[1], ULTRASONIC_POSITION[2], ULTRASONIC_HALF_ANGLE,
                ULTRASONIC_MAX_RANGE);
        put(p, CAMERA_0, CAMERA_POSITION[0], CAMERA_POSITION[1], CAMERA_POSITION[2], CAMERA_PITCH_DOWN, CAMERA_FOV_X,
                CAMERA_FOV_Y, DEPTH_MAX_RANGE);
        p[IR_PERIOD] = IR_PERIOD_TICKS;
        p[US_PERIOD] = ULTRASONIC_PERIOD_TICKS;
        p[DEPTH_ROW_PERIOD] = DEPTH_ROW_PERIOD_TICKS;
        p[RANGE_SENSORS] = options.rangeSensors() ? 1 : 0;
        p[NOISE] = options.sensorNoise() ? 1 : 0;
        p[NOISE_SEED] = options.noiseSeed();
        return p;
    }

    private static void put(double[] p, int at, double... values) {
        System.arraycopy(values, 0, p, at, values.length);
    }
}
