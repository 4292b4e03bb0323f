/*
 * roq_state: everything that changes while the robot runs (like MuJoCo's mjData) — MuJoCo's data, the fragile
 * cells' load and breakage, the noise streams, the command and stimuli taken from the block, the counters, and the
 * stage (a private copy of the shared block the tick writes, published under the seqlock). Sized once by
 * roq_state_open; the tick allocates nothing.
 */
#ifndef ROQ_STATE_H
#define ROQ_STATE_H

#include <stdint.h>
#include <mujoco/mujoco.h>
#include "roq_layout.h"

/* A fragile cell's state (its figures are roq_fragile_cell). */
typedef struct {
    double load;                  /* N, normal force of this tick's contacts */
    int load_ticks;               /* consecutive ticks over its strength */
    unsigned char broken;
} roq_cell_state;

/* One entry of the stimulus table as taken from the block. */
typedef struct {
    int64_t kind;                 /* X_KIND_PUSH or X_KIND_BREAK */
    int64_t first, end;           /* ticks, end exclusive */
    double value[3];              /* force N (world) or value[0] = the cell */
} roq_stimulus;

typedef struct roq_state {
    mjData *d;
    roq_cell_state cell[ROQ_MAX_FRAGILE];
    int broken_count;
    /* model edits queued for roq_model_apply_edits: cells broken since the last safe point, in order */
    int pending_break[ROQ_MAX_FRAGILE];
    int npending_breaks;

    double imu_bias[6];           /* drawn at open from the IMU stream, fixed for the run: gyro rad/s, accel m/s^2 */
    uint64_t noise_state;         /* xorshift64* stream of the older sensors */
    uint64_t imu_noise_state;     /* the IMU's own stream, so the older sensors' noise is unchanged */

    int64_t last_stimulus_seq;
    int nstimuli;                 /* the stimulus table as last taken from the block */
    roq_stimulus stimulus[ROQ_MAX_STIMULI];

    double target[ROQ_JOINTS];
    double wheel_target[ROQ_LEGS];
    int64_t last_command_seq;
    int64_t tick;
    int64_t snapshot_seq;
    int64_t depth_frames;
    int applied_slot;             /* the ring slot written this tick, for publish to copy; -1 none */
    int histogram_bin;            /* the latency bin counted this tick, for publish to copy; -1 none */

    unsigned char *block;         /* Java's direct buffer (not owned) */
    unsigned char *stage;         /* same layout; the tick writes here, publish copies under the seqlock */
} roq_state;

/* block access */
#define BLK_D(b, off) ((double *)((b) + (off)))
#define BLK_F(b, off) ((float *)((b) + (off)))
#define BLK_L(b, off) ((int64_t *)((b) + (off)))
#define BLK_I(b, off) ((int32_t *)((b) + (off)))

#endif
