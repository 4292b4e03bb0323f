package org.fdnet.roq.sim;

/**
 * The simulated RoQ's constants: the single source of truth for the MJCF model ({@link MjcfWriter} writes the
 * model from these numbers) and for a gait or inverse kinematics in Java. {@code RoqGeometryTest} loads the model
 * into MuJoCo and checks that masses, joint ranges and foot positions agree with these figures, so the two cannot
 * drift. Every figure is marked sourced or assumed in {@code docs/explanation/roq-sim.md}.
 *
 * <p>Frames: body frame x forward, y left, z up, origin at the body's centre. Each leg's frame sits at its hip
 * ({@link #hipPosition}) and is turned about z by {@link #hipYawOffset} so its x axis points outward (sprawling
 * legs stand out sideways). In that frame, joint 0 ({@code yaw}) turns the whole leg about z, joint 1
 * ({@code lift}) raises the thigh (positive = foot up), joint 2 ({@code knee}) bends the shank down (0 = leg
 * straight). See {@link #footInBody}.
 */
public final class RoqGeometry {
    private RoqGeometry() {
    }

    /** Legs, in joint order. */
    public static final int LEGS = 4;
    /** Joints per leg. */
    public static final int JOINTS_PER_LEG = 3;
    /** Joints in all, the length of every joint array in the API. */
    public static final int JOINTS = LEGS * JOINTS_PER_LEG;

    /** Leg names in order: front left, front right, hind left, hind right. */
    public static final String[] LEG_NAMES = {"fl", "fr", "hl", "hr"};
    /** Joint names within a leg, in order. */
    public static final String[] JOINT_KIND_NAMES = {"yaw", "lift", "knee"};

    /** Index of leg {@code leg}'s joint {@code kind} (0 yaw, 1 lift, 2 knee) in every joint array. */
    public static int jointIndex(int leg, int kind) {
        return leg * JOINTS_PER_LEG + kind;
    }

    /** The MJCF name of joint {@code j}, e.g. {@code fl_lift}. */
    public static String jointName(int j) {
        return LEG_NAMES[j / JOINTS_PER_LEG] + "_" + JOINT_KIND_NAMES[j % JOINTS_PER_LEG];
    }

    /** The MJCF name of leg {@code leg}'s foot geom, e.g. {@code fl_foot}. */
    public static String footName(int leg) {
        return LEG_NAMES[leg] + "_foot";
    }

    // ---- body ---------------------------------------------------------------------------------------------
    /** Body box length (x), m. */
    public static final double BODY_LENGTH = 0.60;
    /** Body box width (y), m. */
    public static final double BODY_WIDTH = 0.30;
    /** Body box height (z), m. */
    public static final double BODY_HEIGHT = 0.10;
    /** Body mass with its electronics and sensors, kg. */
    public static final double BODY_MASS = 10.2;

    // ---- legs ---------------------------------------------------------------------------------------------
    /** Hip positions in the body frame, m, per leg: {x, y, z}. */
    public static final double[][] HIP_POSITION = {
            {0.25, 0.15, 0.0}, {0.25, -0.15, 0.0}, {-0.25, 0.15, 0.0}, {-0.25, -0.15, 0.0}};
    /** Angle about z from the body's x axis to each leg's outward x axis, rad: left legs +90°, right legs −90°. */
    public static final double[] HIP_YAW_OFFSET = {Math.PI / 2, -Math.PI / 2, Math.PI / 2, -Math.PI / 2};
    /** Hip yaw axis to lift axis (the coxa), m. */
    public static final double COXA_LENGTH = 0.06;
    /** Lift axis to knee axis (the thigh), m. */
    public static final double THIGH_LENGTH = 0.25;
    /** Knee axis to the foot sphere's centre (the shank), m. */
    public static final double SHANK_LENGTH = 0.30;
    /** Foot sphere radius (the sole's tactile sensor), m. */
    public static final double FOOT_RADIUS = 0.03;
    /** Coxa mass, kg. */
    public static final double COXA_MASS = 0.6;
    /** Thigh mass (with its two motors and wire drive), kg. */
    public static final double THIGH_MASS = 1.2;
    /** Shank mass, kg. */
    public static final double SHANK_MASS = 0.3;
    /** Foot mass (sole with its tactile sensor, wheel and its motor), kg. */
    public static final double FOOT_MASS = 0.1;
    /** The whole robot's mass, kg. */
    public static final double TOTAL_MASS = BODY_MASS + LEGS * (COXA_MASS + THIGH_MASS + SHANK_MASS + FOOT_MASS);

    /** Joint lower limits per joint kind (yaw, lift, knee), rad. */
    public static final double[] JOINT_MIN = {-0.9, -0.8, 0.0};
    /** Joint upper limits per joint kind (yaw, lift, knee), rad. */
    public static final double[] JOINT_MAX = {0.9, 1.4, 2.8};

    /** Lower limit of joint {@code j}, rad. */
    public static double jointMin(int j) {
        return JOINT_MIN[j % JOINTS_PER_LEG];
    }

    /** Upper limit of joint {@code j}, rad. */
    public static double jointMax(int j) {
        return JOINT_MAX[j % JOINTS_PER_LEG];
    }

    /** Standing pose per joint kind (yaw, lift, knee), rad: thigh 0.5 rad up, shank vertical. */
    public static final double[] STANDING_POSE = {0.0, 0.5, 0.5 + Math.PI / 2};

    /** Height of the body centre when standing on flat ground in {@link #standingTargets}, m. */
    public static double standingHeight() {
        double[] foot = new double[3];
        footInBody(0, STANDING_POSE[0], STANDING_POSE[1], STANDING_POSE[2], foot);
        return -foot[2] + FOOT_RADIUS;
    }

    /** Fills {@code targets} (length {@link #JOINTS}) with the standing pose for every leg. */
    public static double[] standingTargets(double[] targets) {
        for (int j = 0; j < JOINTS; j++) {
            targets[j] = STANDING_POSE[j % JOINTS_PER_LEG];
        }
        return targets;
    }

    // ---- servo and motor (one kind for all 12 joints) ------------------------------------------------------
    /** Motor torque constant, N·m/A. */
    public static final double MOTOR_TORQUE_CONSTANT = 0.0235;
    /** Motor winding resistance, Ω. */
    public static final double MOTOR_RESISTANCE = 2.3;
    /** Supply voltage, V. */
    public static final double SUPPLY_VOLTAGE = 24.0;
    /** Current limit of the servo amplifier, A. */
    public static final double CURRENT_LIMIT = 4.0;
    /** Gear ratio motor → joint (gearhead times wire pulleys). */
    public static final double GEAR_RATIO = 300.0;
    /** Transmission efficiency. */
    public static final double GEAR_EFFICIENCY = 0.75;
    /** Rotor inertia, kg·m² (reflected to the joint as armature: times the gear ratio squared). */
    public static final double ROTOR_INERTIA = 1.08e-6;
    /** Coulomb friction at the joint, N·m. */
    public static final double JOINT_FRICTION = 0.3;
    /** Viscous friction at the joint, N·m·s/rad. */
    public static final double JOINT_DAMPING = 0.05;
    /** Servo position gain, N·m/rad. */
    public static final double SERVO_KP = 200.0;
    /** Servo velocity gain, N·m·s/rad. */
    public static final double SERVO_KD = 4.0;

    /** Joint torque at the current limit, N·m. */
    public static double maxJointTorque() {
        return MOTOR_TORQUE_CONSTANT * GEAR_RATIO * GEAR_EFFICIENCY * CURRENT_LIMIT;
    }

    /** Joint speed at which the back-EMF equals the supply voltage (no-load speed), rad/s. */
    public static double noLoadJointSpeed() {
        return SUPPLY_VOLTAGE / (MOTOR_TORQUE_CONSTANT * GEAR_RATIO);
    }

    /** Armature (reflected rotor inertia) at each joint, kg·m². */
    public static double armature() {
        return ROTOR_INERTIA * GEAR_RATIO * GEAR_RATIO;
    }

    // ---- sensors ------------------------------------------------------------------------------------------
    /** Control period, s (1 kHz). */
    public static final double TIMESTEP = 0.001;
    /** Infrared range sensor: position in the body frame, m. It looks ahead and 30° down. */
    public static final double[] IR_POSITION = {0.30, 0.0, 0.0};
    /** Infrared ray's downward pitch, rad. */
    public static final double IR_PITCH_DOWN = Math.toRadians(30);
    /** Infrared maximum range, m (beyond: reported as this). */
    public static final double IR_MAX_RANGE = 0.8;
    /** Ultrasonic sensor position in the body frame, m. It looks straight ahead. */
    public static final double[] ULTRASONIC_POSITION = {0.30, 0.0, 0.03};
    /** Ultrasonic maximum range, m. */
    public static final double ULTRASONIC_MAX_RANGE = 3.0;
    /** Ultrasonic beam half angle, rad (three rays: centre, ±half angle; the nearest echo wins). */
    public static final double ULTRASONIC_HALF_ANGLE = Math.toRadians(15);
    /** CCD camera position in the body frame, m. */
    public static final double[] CAMERA_POSITION = {0.30, 0.0, 0.05};
    /** Camera's downward pitch, rad. */
    public static final double CAMERA_PITCH_DOWN = Math.toRadians(20);
    /** Depth image width, pixels. */
    public static final int DEPTH_WIDTH = 32;
    /** Depth image height, pixels. */
    public static final int DEPTH_HEIGHT = 24;
    /**
     * The depth image advances by one row's worth of pixels every this many ticks, spread evenly (4 rays a tick):
     * a full image every 192 ms (≈ 5 Hz). Rays are the tick's dearest part (≈ 0.65 µs each against the
     * heightfield here, up to 30 µs for a long one over a tall heightfield), so few go in any one tick.
     */
    public static final int DEPTH_ROW_PERIOD_TICKS = 8;
    /** The infrared range refreshes every this many ticks (100 Hz). */
    public static final int IR_PERIOD_TICKS = 10;
    /** The ultrasonic range refreshes every this many ticks (50 Hz: a 3 m echo alone takes 17.5 ms). */
    public static final int ULTRASONIC_PERIOD_TICKS = 20;
    /** Horizontal field of view, rad. */
    public static final double CAMERA_FOV_X = Math.toRadians(60);
    /** Vertical field of view, rad. */
    public static final double CAMERA_FOV_Y = Math.toRadians(45);
    /** Depth beyond which the image reports this value, m. */
    public static final double DEPTH_MAX_RANGE = 4.0;
    /**
     * Wheel mechanism: the foot sphere turns on its own axle at the shank's end (axis across the leg's plane), so
     * each foot is also a wheel of {@link #FOOT_RADIUS}. Without a wheel command the axle is braked.
     */
    public static final double WHEEL_RADIUS = FOOT_RADIUS;
    /** Wheel speed servo gain, N·m·s/rad (also the brake when no wheel speed is commanded). */
    public static final double WHEEL_KV = 2.0;
    /** Wheel motor torque limit, N·m. */
    public static final double WHEEL_MAX_TORQUE = 3.0;
    /** Wheel speed limit, rad/s. */
    public static final double WHEEL_MAX_SPEED = 10.0;

    /**
     * Forward kinematics of the whole leg: writes the hip (yaw axis), the lift axis, the knee and the foot centre in
     * the body frame into {@code out} as 12 numbers {x, y, z} × 4. Returns {@code out}.
     */
    public static double[] legInBody(int leg, double yaw, double lift, double knee, double[] out) {
        double heading = HIP_YAW_OFFSET[leg] + yaw;
        double cx = Math.cos(heading);
        double sy = Math.sin(heading);
        double[] reach = {0, COXA_LENGTH, COXA_LENGTH + THIGH_LENGTH * Math.cos(lift),
                COXA_LENGTH + THIGH_LENGTH * Math.cos(lift) + SHANK_LENGTH * Math.cos(lift - knee)};
        double[] up = {0, 0, THIGH_LENGTH * Math.sin(lift),
                THIGH_LENGTH * Math.sin(lift) + SHANK_LENGTH * Math.sin(lift - knee)};
        for (int k = 0; k < 4; k++) {
            out[3 * k] = HIP_POSITION[leg][0] + reach[k] * cx;
            out[3 * k + 1] = HIP_POSITION[leg][1] + reach[k] * sy;
            out[3 * k + 2] = HIP_POSITION[leg][2] + up[k];
        }
        return out;
    }

    /**
     * Forward kinematics: the foot sphere's centre in the body frame for leg {@code leg} at joint angles
     * ({@code yaw}, {@code lift}, {@code knee}), written into {@code out} = {x, y, z}. Returns {@code out}.
     */
    public static double[] footInBody(int leg, double yaw, double lift, double knee, double[] out) {
        double reach = COXA_LENGTH + THIGH_LENGTH * Math.cos(lift) + SHANK_LENGTH * Math.cos(lift - knee);
        double z = THIGH_LENGTH * Math.sin(lift) + SHANK_LENGTH * Math.sin(lift - knee);
        double heading = HIP_YAW_OFFSET[leg] + yaw;
        out[0] = HIP_POSITION[leg][0] + reach * Math.cos(heading);
        out[1] = HIP_POSITION[leg][1] + reach * Math.sin(heading);
        out[2] = HIP_POSITION[leg][2] + z;
        return out;
    }
}
