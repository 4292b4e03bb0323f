package org.fdnet.roq.sim;

import static org.fdnet.roq.sim.RoqGeometry.*;

import java.util.List;

/**
 * The figures the C loop needs, handed over at open: the parameter array ({@code P_*} indices, unpacked by
 * {@code roq_model.c} into named structs) and the fragile cells' figures ({@code F_STRIDE} doubles per cell). Built
 * from {@link RoqGeometry}, so C holds no figure of its own. {@link LayoutHandshake} checks every constant here by
 * name against the {@code ROQ_LAYOUT} table of {@code src/main/c/roq_layout.h} at load.
 */
final class NativeParameters {
    static final int P_KP = 0;
    static final int P_KD = 1;
    static final int P_TORQUE_CONSTANT = 2;
    static final int P_RESISTANCE = 3;
    static final int P_SUPPLY_VOLTAGE = 4;
    static final int P_CURRENT_LIMIT = 5;
    static final int P_GEAR = 6;
    static final int P_EFFICIENCY = 7;
    static final int P_WHEEL_KV = 8;
    static final int P_WHEEL_TORQUE = 9;
    static final int P_WHEEL_SPEED = 10;
    static final int P_JOINT_MIN_0 = 11;   // 3 values
    static final int P_JOINT_MAX_0 = 14;   // 3 values
    static final int P_INITIAL_POSE_0 = 17; // 3 values
    static final int P_BREAK_HOLD_TICKS = 20;
    static final int P_IR_0 = 21;          // x y z pitchDown maxRange
    static final int P_US_0 = 26;          // x y z halfAngle maxRange
    static final int P_CAMERA_0 = 31;      // x y z pitchDown fovX fovY maxRange
    static final int P_NOISE = 38;         // 1 = on
    static final int P_NOISE_SEED = 39;
    static final int P_IR_PERIOD = 40;
    static final int P_US_PERIOD = 41;
    static final int P_DEPTH_ROW_PERIOD = 42;
    static final int P_RANGE_SENSORS = 43; // 1 = on
    static final int P_COUNT = 44;

    // one fragile cell's figures
    static final int F_X = 0;
    static final int F_Y = 1;
    static final int F_SIZE_X = 2;
    static final int F_SIZE_Y = 3;
    static final int F_HEIGHT = 4;
    static final int F_STRENGTH = 5;
    static final int F_STRIDE = 6;

    private NativeParameters() {
    }

    static double[] of(SimOptions options) {
        double[] p = new double[P_COUNT];
        p[P_KP] = SERVO_KP;
        p[P_KD] = SERVO_KD;
        p[P_TORQUE_CONSTANT] = MOTOR_TORQUE_CONSTANT;
        p[P_RESISTANCE] = MOTOR_RESISTANCE;
        p[P_SUPPLY_VOLTAGE] = SUPPLY_VOLTAGE;
        p[P_CURRENT_LIMIT] = CURRENT_LIMIT;
        p[P_GEAR] = GEAR_RATIO;
        p[P_EFFICIENCY] = GEAR_EFFICIENCY;
        p[P_WHEEL_KV] = WHEEL_KV;
        p[P_WHEEL_TORQUE] = WHEEL_MAX_TORQUE;
        p[P_WHEEL_SPEED] = WHEEL_MAX_SPEED;
        for (int k = 0; k < JOINTS_PER_LEG; k++) {
            p[P_JOINT_MIN_0 + k] = JOINT_MIN[k];
            p[P_JOINT_MAX_0 + k] = JOINT_MAX[k];
            p[P_INITIAL_POSE_0 + k] = STANDING_POSE[k];
        }
        p[P_BREAK_HOLD_TICKS] = Math.round(FragileCell.BREAK_HOLD_SECONDS / TIMESTEP);
        put(p, P_IR_0, IR_POSITION[0], IR_POSITION[1], IR_POSITION[2], IR_PITCH_DOWN, IR_MAX_RANGE);
        put(p, P_US_0, ULTRASONIC_POSITION[0], ULTRASONIC_POSITION[1], ULTRASONIC_POSITION[2], ULTRASONIC_HALF_ANGLE,
                ULTRASONIC_MAX_RANGE);
        put(p, P_CAMERA_0, CAMERA_POSITION[0], CAMERA_POSITION[1], CAMERA_POSITION[2], CAMERA_PITCH_DOWN,
                CAMERA_FOV_X, CAMERA_FOV_Y, DEPTH_MAX_RANGE);
        p[P_IR_PERIOD] = IR_PERIOD_TICKS;
        p[P_US_PERIOD] = ULTRASONIC_PERIOD_TICKS;
        p[P_DEPTH_ROW_PERIOD] = DEPTH_ROW_PERIOD_TICKS;
        p[P_RANGE_SENSORS] = options.rangeSensors() ? 1 : 0;
        p[P_NOISE] = options.sensorNoise() ? 1 : 0;
        p[P_NOISE_SEED] = options.noiseSeed();
        return p;
    }

    /** The cells' figures, {@link #F_STRIDE} doubles per cell in course order. */
    static double[] fragileFigures(List<FragileCell> cells) {
        double[] f = new double[cells.size() * F_STRIDE];
        for (int i = 0; i < cells.size(); i++) {
            FragileCell c = cells.get(i);
            put(f, F_STRIDE * i + F_X, c.x(), c.y());
            put(f, F_STRIDE * i + F_SIZE_X, c.sizeX(), c.sizeY());
            f[F_STRIDE * i + F_HEIGHT] = c.height();
            f[F_STRIDE * i + F_STRENGTH] = c.strength();
        }
        return f;
    }

    private static void put(double[] p, int at, double... values) {
        System.arraycopy(values, 0, p, at, values.length);
    }
}
