package org.fdnet.roq.sim;

/**
 * The byte layout of the one direct buffer Java and the C joint loop share. The C side's one source is the
 * {@code ROQ_LAYOUT} table in {@code src/main/c/roq_layout.h}; at load {@link LayoutHandshake} compares every
 * {@code int} and {@code long} constant of this class by name with that table (and every table entry with a
 * constant here or in {@link NativeParameters}), so a field moved, added or dropped on one side only fails the
 * load and is named. All numbers are in the platform's byte order; doubles are IEEE 754, 8-byte aligned.
 *
 * <pre>
 *  0      int32  layout version ({@link #VERSION})
 *  8      int64  snapshot sequence: odd while the loop writes, even when the snapshot is consistent
 *  16     int64  command sequence:  odd while Java writes the command slot, even when it is complete
 *  64     snapshot  (written by C once per tick under the snapshot sequence)
 *  4096   loop statistics (same sequence), with the tick at which the last command was applied and the
 *         snapshot tick it was based on (4184, 4192; version 3)
 *  12224  reflex histogram (same sequence; version 3)
 *  12288  command slot (written by Java under the command sequence, read by C at the start of a tick)
 *  16384  end
 * </pre>
 */
public final class SharedBlockLayout {
    private SharedBlockLayout() {
    }

    /** Layout version; changes whenever an offset does. */
    public static final int VERSION = 5;
    /** Size of the block, bytes. */
    public static final int BLOCK_SIZE = 16384;

    // the robot's figures that size the arrays below (checked with the offsets, so C cannot size them otherwise)
    public static final int LEGS = RoqGeometry.LEGS;
    public static final int JOINTS_PER_LEG = RoqGeometry.JOINTS_PER_LEG;
    public static final int JOINTS = RoqGeometry.JOINTS;
    public static final int DEPTH_WIDTH = RoqGeometry.DEPTH_WIDTH;
    public static final int DEPTH_HEIGHT = RoqGeometry.DEPTH_HEIGHT;
    /** Fragile cells a course may have: the broken-cell mask holds this many bits. */
    public static final int MAX_FRAGILE = Course.MAX_FRAGILE_CELLS;

    public static final int LAYOUT_VERSION = 0;
    public static final int SNAPSHOT_SEQ = 8;
    public static final int COMMAND_SEQ = 16;
    /** Stimulus sequence: odd while Java writes the stimulus table (version 4). */
    public static final int STIMULUS_SEQ = 24;

    // snapshot
    public static final int S_TICK = 64;
    public static final int S_TIME = 72;
    public static final int S_JOINT_ANGLE = 80;
    public static final int S_JOINT_VELOCITY = 176;
    public static final int S_JOINT_TORQUE = 272;
    public static final int S_ROLL = 368;
    public static final int S_PITCH = 376;
    public static final int S_FOOT_FORCE = 384;
    public static final int S_IR_RANGE = 416;
    public static final int S_ULTRASONIC_RANGE = 424;
    public static final int S_BODY_POSITION = 432;
    public static final int S_BODY_QUATERNION = 456;
    public static final int S_CENTRE_OF_MASS = 488;
    public static final int S_WHEEL_SPEED = 512;
    public static final int S_BROKEN_COUNT = 544;
    public static final int S_BROKEN_MASK = 552;
    public static final int S_DEPTH_FRAMES = 584;
    public static final int S_DEPTH = 592;
    /** IMU gyro: body-frame angular rate, rad/s, double[3] (version 4). */
    public static final int S_GYRO = S_DEPTH + 4 * RoqGeometry.DEPTH_WIDTH * RoqGeometry.DEPTH_HEIGHT;
    /** IMU accelerometer: body-frame specific force (reads +g upward at rest), m/s², double[3]. */
    public static final int S_ACCEL = S_GYRO + 24;
    /** Ground truth: the external push on the body this tick, world frame, N, double[3]. */
    public static final int S_PUSH_FORCE = S_ACCEL + 24;
    public static final int S_END = S_PUSH_FORCE + 24;

    // loop statistics
    public static final int T_TICKS = 4096;
    public static final int T_OVERRUNS = 4104;
    public static final int T_MAX_OVERRUN_NS = 4112;
    public static final int T_MAX_LATENCY_NS = 4120;
    public static final int T_LATENCY_SAMPLES = 4128;
    public static final int T_COMMANDS_APPLIED = 4136;
    public static final int T_COMMANDS_NAN = 4144;
    public static final int T_COMMANDS_OUT_OF_RANGE = 4152;
    public static final int T_COMMANDS_STALE = 4160;
    public static final int T_RT_FLAGS = 4168;
    public static final int T_MAX_TICK_NS = 4176;
    /** The tick counter when the loop applied the last command (it first shows in snapshot tick + 1). */
    public static final int T_LAST_APPLIED_TICK = 4184;
    /** The snapshot tick that last applied command was based on ({@link #C_ISSUED_TICK}). */
    public static final int T_LAST_APPLIED_BASED_ON = 4192;
    public static final int T_HISTOGRAM = 4224;
    /**
     * Reflex histogram: int32 counts of applied commands by ticks from the snapshot the command was based on to
     * the first snapshot computed under it (1 = applied at the very next tick); the last bin also holds later ones.
     */
    public static final int T_REFLEX_HISTOGRAM = 12224;
    /** Bins of {@link #T_REFLEX_HISTOGRAM}. */
    public static final int REFLEX_BINS = 16;
    /** Latency histogram: int32 counts of 1 µs bins; the last bin also holds everything later. */
    public static final int HISTOGRAM_BINS = 2000;

    // command slot
    public static final int C_ISSUED_TICK = 12288;
    public static final int C_TARGETS = 12296;
    public static final int C_WHEEL_SPEED = 12392;
    public static final int C_FLAGS = 12424;
    /** The newest snapshot the command was computed from: 0 none, negative = {@link #C_ISSUED_TICK} (version 5). */
    public static final int C_SOURCE_TICK = 12432;
    /**
     * Applied-command ring (under the snapshot sequence): command n (from 1; {@link #T_COMMANDS_APPLIED} counts them)
     * at slot (n − 1) % {@link #APPLIED_RING}: int64 the tick it was applied at, int64 its source tick.
     */
    public static final int A_RING = 14080;
    public static final int A_ENTRY_SIZE = 16;
    public static final int APPLIED_RING = 64;
    /** C_FLAGS bit: the wheel speeds are to be driven (else the wheels are braked). */
    public static final long FLAG_WHEELS = 1;

    // stimulus table (written by Java under STIMULUS_SEQ; the tick applies it)
    public static final int X_COUNT = 12440;
    public static final int X_TABLE = 12448;
    /** One entry: int64 kind, int64 first tick, int64 end tick (exclusive), double[3] force (N) or cell index. */
    public static final int X_ENTRY_SIZE = 48;
    public static final int MAX_STIMULI = 32;
    public static final long X_KIND_PUSH = 1;
    public static final long X_KIND_BREAK = 2;

    /** T_RT_FLAGS bits: what the real-time loop obtained. */
    public static final long RT_SCHED_FIFO = 1;
    public static final long RT_MLOCKALL = 2;
    public static final long RT_DMA_LATENCY = 4;

    /** A command older than this many ticks when the loop sees it is ignored and counted stale. */
    public static final int STALE_TICKS = 100;
}
