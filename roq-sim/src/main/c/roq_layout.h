/*
 * Everything Java and C must agree on, in ONE table: the byte layout of the block they share, the robot's figures
 * that size its arrays, the indices of the parameter array handed over at open and the figures of one fragile
 * cell. ROQ_LAYOUT below is that table; the enum the C code uses and the table roq_jni.c exports to Java
 * (RoqNative.layoutNames/layoutValues) are both expanded from it, so the two cannot drift. At load
 * RoqNativeLibrary compares every entry by name with the constant of the same name in
 * org.fdnet.roq.sim.SharedBlockLayout or NativeParameters (a leading "ROQ_" is not part of the name), and every
 * such Java constant with the table: a field moved, added or dropped on one side only fails the load, naming it.
 */
#ifndef ROQ_LAYOUT_H
#define ROQ_LAYOUT_H

/* X(name, value): one entry per shared figure. Layout entries are byte offsets into the block unless the comment
   says otherwise. */
#define ROQ_LAYOUT(X)                                                                                                \
    /* sizes and versions */                                                                                         \
    X(ROQ_VERSION, 5)            /* the layout version: changes whenever an offset does */                           \
    X(ROQ_BLOCK_SIZE, 16384)     /* bytes */                                                                         \
    X(ROQ_HISTOGRAM_BINS, 2000)  /* 1 µs latency bins; the last also holds everything later */                       \
    X(ROQ_REFLEX_BINS, 16)                                                                                           \
    X(ROQ_STALE_TICKS, 100)      /* a command older than this when the loop sees it is ignored */                    \
    X(ROQ_MAX_STIMULI, 32)                                                                                           \
    X(ROQ_APPLIED_RING, 64)                                                                                          \
    X(ROQ_LEGS, 4)                                                                                                   \
    X(ROQ_JOINTS_PER_LEG, 3)     /* yaw, lift, knee (the wheels are apart) */                                        \
    X(ROQ_JOINTS, ROQ_LEGS * ROQ_JOINTS_PER_LEG)                                                                     \
    X(ROQ_DEPTH_WIDTH, 32)       /* pixels of the depth image */                                                     \
    X(ROQ_DEPTH_HEIGHT, 24)                                                                                          \
    X(ROQ_MAX_FRAGILE, 256)      /* fragile cells a course may have */                                               \
    /* header */                                                                                                     \
    X(LAYOUT_VERSION, 0)         /* int32 ROQ_VERSION */                                                             \
    X(SNAPSHOT_SEQ, 8)           /* int64, odd while the loop publishes */                                           \
    X(COMMAND_SEQ, 16)           /* int64, odd while Java writes the command slot */                                 \
    X(STIMULUS_SEQ, 24)          /* int64, odd while Java writes the stimulus table */                               \
    /* snapshot (under the snapshot sequence) */                                                                     \
    X(S_TICK, 64)                                                                                                    \
    X(S_TIME, 72)                                                                                                    \
    X(S_JOINT_ANGLE, 80)         /* double[12] */                                                                    \
    X(S_JOINT_VELOCITY, 176)     /* double[12] */                                                                    \
    X(S_JOINT_TORQUE, 272)       /* double[12] */                                                                    \
    X(S_ROLL, 368)                                                                                                   \
    X(S_PITCH, 376)                                                                                                  \
    X(S_FOOT_FORCE, 384)         /* double[4] */                                                                     \
    X(S_IR_RANGE, 416)                                                                                               \
    X(S_ULTRASONIC_RANGE, 424)                                                                                       \
    X(S_BODY_POSITION, 432)      /* double[3] */                                                                     \
    X(S_BODY_QUATERNION, 456)    /* double[4] w x y z */                                                             \
    X(S_CENTRE_OF_MASS, 488)     /* double[3] */                                                                     \
    X(S_WHEEL_SPEED, 512)        /* double[4] */                                                                     \
    X(S_BROKEN_COUNT, 544)                                                                                           \
    X(S_BROKEN_MASK, 552)        /* int64[4]: bit i = fragile cell i broken */                                       \
    X(S_DEPTH_FRAMES, 584)                                                                                           \
    X(S_DEPTH, 592)              /* float[ROQ_DEPTH_WIDTH * ROQ_DEPTH_HEIGHT] */                                     \
    X(S_GYRO, S_DEPTH + 4 * ROQ_DEPTH_WIDTH * ROQ_DEPTH_HEIGHT) /* double[3] body-frame angular rate, rad/s */       \
    X(S_ACCEL, S_GYRO + 24)      /* double[3] body-frame specific force, m/s^2 */                                    \
    X(S_PUSH_FORCE, S_ACCEL + 24) /* double[3] ground truth: external push, N, world */                              \
    X(S_END, S_PUSH_FORCE + 24)                                                                                      \
    /* loop statistics (same sequence) */                                                                            \
    X(T_TICKS, 4096)                                                                                                 \
    X(T_OVERRUNS, 4104)                                                                                              \
    X(T_MAX_OVERRUN_NS, 4112)                                                                                        \
    X(T_MAX_LATENCY_NS, 4120)                                                                                        \
    X(T_LATENCY_SAMPLES, 4128)                                                                                       \
    X(T_COMMANDS_APPLIED, 4136)                                                                                      \
    X(T_COMMANDS_NAN, 4144)                                                                                          \
    X(T_COMMANDS_OUT_OF_RANGE, 4152)                                                                                 \
    X(T_COMMANDS_STALE, 4160)                                                                                        \
    X(T_RT_FLAGS, 4168)          /* RT_* bits */                                                                     \
    X(T_MAX_TICK_NS, 4176)                                                                                           \
    X(T_LAST_APPLIED_TICK, 4184)                                                                                     \
    X(T_LAST_APPLIED_BASED_ON, 4192)                                                                                 \
    X(T_HISTOGRAM, 4224)         /* int32[ROQ_HISTOGRAM_BINS] */                                                     \
    X(T_REFLEX_HISTOGRAM, 12224) /* int32[ROQ_REFLEX_BINS]: ticks from a command's source snapshot to the first      \
                                    snapshot computed under it */                                                    \
    /* command slot (under the command sequence, written by Java) */                                                 \
    X(C_ISSUED_TICK, 12288)                                                                                          \
    X(C_TARGETS, 12296)          /* double[12] */                                                                    \
    X(C_WHEEL_SPEED, 12392)      /* double[4] */                                                                     \
    X(C_FLAGS, 12424)            /* FLAG_* bits */                                                                   \
    X(C_SOURCE_TICK, 12432)      /* the newest snapshot the command was computed from; 0 none, <0 = issued */        \
    X(FLAG_WHEELS, 1)            /* C_FLAGS bit: drive the wheels (else brake them) */                               \
    /* stimulus table (under the stimulus sequence, written by Java): pushes and cell breaks the tick applies */     \
    X(X_COUNT, 12440)                                                                                                \
    X(X_TABLE, 12448)                                                                                                \
    X(X_ENTRY_SIZE, 48)          /* int64 kind, int64 first tick, int64 end tick (exclusive), double[3] */           \
    X(X_KIND_PUSH, 1)            /* double[3]: force, N, world */                                                    \
    X(X_KIND_BREAK, 2)           /* double[0]: the fragile cell */                                                   \
    /* applied-command ring (under the snapshot sequence): command n (from 1) at slot (n - 1) % ROQ_APPLIED_RING:    \
       int64 the tick it was applied at (it first shows in snapshot tick + 1), int64 its source tick */              \
    X(A_RING, 14080)                                                                                                 \
    X(A_ENTRY_SIZE, 16)                                                                                              \
    /* T_RT_FLAGS bits: what the real-time loop obtained */                                                          \
    X(RT_SCHED_FIFO, 1)                                                                                              \
    X(RT_MLOCKALL, 2)                                                                                                \
    X(RT_DMA_LATENCY, 4)                                                                                             \
    /* the parameter array (double[P_COUNT], handed over at open; roq_model.c unpacks it into roq_params) */         \
    X(P_KP, 0)                                                                                                       \
    X(P_KD, 1)                                                                                                       \
    X(P_TORQUE_CONSTANT, 2)                                                                                          \
    X(P_RESISTANCE, 3)                                                                                               \
    X(P_SUPPLY_VOLTAGE, 4)                                                                                           \
    X(P_CURRENT_LIMIT, 5)                                                                                            \
    X(P_GEAR, 6)                                                                                                     \
    X(P_EFFICIENCY, 7)                                                                                               \
    X(P_WHEEL_KV, 8)                                                                                                 \
    X(P_WHEEL_TORQUE, 9)                                                                                             \
    X(P_WHEEL_SPEED, 10)                                                                                             \
    X(P_JOINT_MIN_0, 11)         /* 3: yaw, lift, knee */                                                            \
    X(P_JOINT_MAX_0, 14)         /* 3 */                                                                             \
    X(P_INITIAL_POSE_0, 17)      /* 3 */                                                                             \
    X(P_BREAK_HOLD_TICKS, 20)                                                                                        \
    X(P_IR_0, 21)                /* 5: x y z pitchDown maxRange */                                                   \
    X(P_US_0, 26)                /* 5: x y z halfAngle maxRange */                                                   \
    X(P_CAMERA_0, 31)            /* 7: x y z pitchDown fovX fovY maxRange */                                         \
    X(P_NOISE, 38)               /* 1 = on */                                                                        \
    X(P_NOISE_SEED, 39)                                                                                              \
    X(P_IR_PERIOD, 40)                                                                                               \
    X(P_US_PERIOD, 41)                                                                                               \
    X(P_DEPTH_ROW_PERIOD, 42)                                                                                        \
    X(P_RANGE_SENSORS, 43)       /* 1 = on */                                                                        \
    X(P_COUNT, 44)                                                                                                   \
    /* one fragile cell's figures in the array handed over at open (F_STRIDE doubles per cell) */                    \
    X(F_X, 0)                                                                                                        \
    X(F_Y, 1)                                                                                                        \
    X(F_SIZE_X, 2)                                                                                                   \
    X(F_SIZE_Y, 3)                                                                                                   \
    X(F_HEIGHT, 4)                                                                                                   \
    X(F_STRENGTH, 5)                                                                                                 \
    X(F_STRIDE, 6)

#define ROQ_LAYOUT_ENUM(name, value) name = (value),
enum roq_layout { ROQ_LAYOUT(ROQ_LAYOUT_ENUM) };
#undef ROQ_LAYOUT_ENUM

/* The regions do not overlap and fit the block. */
_Static_assert(S_END <= T_TICKS, "snapshot runs into the statistics");
_Static_assert(S_BROKEN_MASK + ROQ_MAX_FRAGILE / 8 <= S_DEPTH_FRAMES, "broken mask too small for ROQ_MAX_FRAGILE");
_Static_assert(T_LAST_APPLIED_BASED_ON + 8 <= T_HISTOGRAM, "statistics run into the histogram");
_Static_assert(T_HISTOGRAM + 4 * ROQ_HISTOGRAM_BINS <= T_REFLEX_HISTOGRAM, "histogram runs into the reflex histogram");
_Static_assert(T_REFLEX_HISTOGRAM + 4 * ROQ_REFLEX_BINS <= C_ISSUED_TICK, "reflex histogram runs into the command");
_Static_assert(C_SOURCE_TICK + 8 <= X_COUNT, "command slot runs into the stimulus table");
_Static_assert(X_TABLE + X_ENTRY_SIZE * ROQ_MAX_STIMULI <= A_RING, "stimulus table runs into the applied ring");
_Static_assert(A_RING + A_ENTRY_SIZE * ROQ_APPLIED_RING <= ROQ_BLOCK_SIZE, "applied ring runs past the block");

#endif
