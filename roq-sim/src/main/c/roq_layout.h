/*
 * The byte layout of the block shared with Java (org.fdnet.roq.sim.SharedBlockLayout holds the same numbers;
 * the ABI handshake compares ROQ_LAYOUT_VERSION and ROQ_BLOCK_SIZE) and the indices of the parameter array
 * (org.fdnet.roq.sim.NativeParameters).
 */
#ifndef ROQ_LAYOUT_H
#define ROQ_LAYOUT_H

#define ROQ_LAYOUT_VERSION 5
#define ROQ_BLOCK_SIZE 16384

#define ROQ_JOINTS 12
#define ROQ_LEGS 4
#define ROQ_DEPTH_W 32
#define ROQ_DEPTH_H 24
#define ROQ_MAX_FRAGILE 256
#define ROQ_HIST_BINS 2000
#define ROQ_STALE_TICKS 100
#define ROQ_REFLEX_BINS 16
#define ROQ_MAX_STIMULI 32
#define ROQ_APPLIED_RING 64

/* header */
#define L_LAYOUT_VERSION 0
#define L_SNAPSHOT_SEQ 8
#define L_COMMAND_SEQ 16
#define L_STIMULUS_SEQ 24

/* snapshot (under the snapshot sequence) */
#define S_TICK 64
#define S_TIME 72
#define S_JOINT_ANGLE 80
#define S_JOINT_VELOCITY 176
#define S_JOINT_TORQUE 272
#define S_ROLL 368
#define S_PITCH 376
#define S_FOOT_FORCE 384
#define S_IR_RANGE 416
#define S_ULTRASONIC_RANGE 424
#define S_BODY_POSITION 432
#define S_BODY_QUATERNION 456
#define S_CENTRE_OF_MASS 488
#define S_WHEEL_SPEED 512
#define S_BROKEN_COUNT 544
#define S_BROKEN_MASK 552
#define S_DEPTH_FRAMES 584
#define S_DEPTH 592
#define S_GYRO (S_DEPTH + 4 * ROQ_DEPTH_W * ROQ_DEPTH_H) /* double[3] body-frame angular rate, rad/s (version 4) */
#define S_ACCEL (S_GYRO + 24)                               /* double[3] body-frame specific force, m/s^2 */
#define S_PUSH_FORCE (S_ACCEL + 24)                         /* double[3] ground truth: external push, N, world */
#define S_END (S_PUSH_FORCE + 24)

/* loop statistics (same sequence) */
#define T_TICKS 4096
#define T_OVERRUNS 4104
#define T_MAX_OVERRUN_NS 4112
#define T_MAX_LATENCY_NS 4120
#define T_LATENCY_SAMPLES 4128
#define T_COMMANDS_APPLIED 4136
#define T_COMMANDS_NAN 4144
#define T_COMMANDS_OUT_OF_RANGE 4152
#define T_COMMANDS_STALE 4160
#define T_RT_FLAGS 4168
#define T_MAX_TICK_NS 4176
#define T_LAST_APPLIED_TICK 4184
#define T_LAST_APPLIED_BASED_ON 4192
#define T_HISTOGRAM 4224
#define T_REFLEX_HISTOGRAM 12224 /* int32 x ROQ_REFLEX_BINS: ticks from the snapshot a command is based on to the first snapshot computed under it */

/* command slot (under the command sequence, written by Java) */
#define C_ISSUED_TICK 12288
#define C_TARGETS 12296
#define C_WHEEL_SPEED 12392
#define C_FLAGS 12424
#define C_SOURCE_TICK 12432 /* the newest snapshot the command was computed from; 0 none, <0 = C_ISSUED_TICK (version 5) */
#define FLAG_WHEELS 1

/* applied-command ring (under the snapshot sequence): command n (from 1, T_COMMANDS_APPLIED counts them) at slot
   (n - 1) % ROQ_APPLIED_RING: int64 the tick it was applied at (it first shows in snapshot tick + 1), int64 its
   source tick (version 5) */
#define A_RING 14080
#define A_ENTRY_SIZE 16

/* stimulus table (under the stimulus sequence, written by Java): pushes and cell breaks the tick applies */
#define X_COUNT 12440
#define X_TABLE 12448
#define X_ENTRY_SIZE 48 /* int64 kind, int64 first tick, int64 end tick (exclusive), double[3] force N or cell */
#define X_KIND_PUSH 1
#define X_KIND_BREAK 2

/* Every offset above in one order, for the handshake: Java compares them with SharedBlockLayout's, field by field,
   so a field moved on one side only is caught by name. Keep the order of SharedBlockLayout.FIELDS. */
#define ROQ_LAYOUT_OFFSETS { L_LAYOUT_VERSION, L_SNAPSHOT_SEQ, L_COMMAND_SEQ, L_STIMULUS_SEQ, \
    S_TICK, S_TIME, S_JOINT_ANGLE, S_JOINT_VELOCITY, S_JOINT_TORQUE, S_ROLL, S_PITCH, S_FOOT_FORCE, S_IR_RANGE, \
    S_ULTRASONIC_RANGE, S_BODY_POSITION, S_BODY_QUATERNION, S_CENTRE_OF_MASS, S_WHEEL_SPEED, S_BROKEN_COUNT, \
    S_BROKEN_MASK, S_DEPTH_FRAMES, S_DEPTH, S_GYRO, S_ACCEL, S_PUSH_FORCE, S_END, \
    T_TICKS, T_OVERRUNS, T_MAX_OVERRUN_NS, T_MAX_LATENCY_NS, T_LATENCY_SAMPLES, T_COMMANDS_APPLIED, T_COMMANDS_NAN, \
    T_COMMANDS_OUT_OF_RANGE, T_COMMANDS_STALE, T_RT_FLAGS, T_MAX_TICK_NS, T_LAST_APPLIED_TICK, \
    T_LAST_APPLIED_BASED_ON, T_HISTOGRAM, T_REFLEX_HISTOGRAM, \
    C_ISSUED_TICK, C_TARGETS, C_WHEEL_SPEED, C_FLAGS, C_SOURCE_TICK, A_RING, A_ENTRY_SIZE, ROQ_APPLIED_RING, X_COUNT, X_TABLE, X_ENTRY_SIZE, ROQ_MAX_STIMULI }

#define RT_SCHED_FIFO 1
#define RT_MLOCKALL 2
#define RT_DMA_LATENCY 4

/* parameter array */
#define P_KP 0
#define P_KD 1
#define P_TORQUE_CONSTANT 2
#define P_RESISTANCE 3
#define P_SUPPLY_VOLTAGE 4
#define P_CURRENT_LIMIT 5
#define P_GEAR 6
#define P_EFFICIENCY 7
#define P_WHEEL_KV 8
#define P_WHEEL_TORQUE 9
#define P_WHEEL_SPEED 10
#define P_JOINT_MIN_0 11
#define P_JOINT_MAX_0 14
#define P_INITIAL_POSE_0 17
#define P_BREAK_HOLD_TICKS 20
#define P_IR_0 21
#define P_US_0 26
#define P_CAMERA_0 31
#define P_NOISE 38
#define P_NOISE_SEED 39
#define P_IR_PERIOD 40
#define P_US_PERIOD 41
#define P_DEPTH_ROW_PERIOD 42
#define P_RANGE_SENSORS 43
#define P_COUNT 44

#endif
