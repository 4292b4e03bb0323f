/*
 * The joint loop's two structs (like MuJoCo's mjModel/mjData): everything lives in one roq_sim, sized once at open;
 * the tick allocates nothing.
 */
#ifndef ROQ_SIM_H
#define ROQ_SIM_H

#include <stdint.h>
#include <pthread.h>
#include <mujoco/mujoco.h>
#include "roq_layout.h"

typedef struct {
    mjModel *m;
    mjData *d;
    double p[P_COUNT];

    int body_id;                       /* the robot's free body */
    int terrain_geom;                  /* the heightfield geom */
    int qadr[ROQ_JOINTS], dadr[ROQ_JOINTS];
    int wheel_dadr[ROQ_LEGS];
    int *geom_role;                    /* per geom: -1, leg 0..3 for a foot, 100 + i for fragile cell i */

    int nfragile;
    int fragile_geom[ROQ_MAX_FRAGILE];
    double fragile_strength[ROQ_MAX_FRAGILE];
    double fragile_height[ROQ_MAX_FRAGILE];
    double fragile_load[ROQ_MAX_FRAGILE];
    int fragile_load_ticks[ROQ_MAX_FRAGILE];
    unsigned char fragile_broken[ROQ_MAX_FRAGILE];
    int broken_count;

    int gyro_adr, accel_adr;           /* MuJoCo's gyro and accelerometer sensors on the body's imu site */
    double imu_bias[6];                /* seeded at open: gyro rad/s, accelerometer m/s^2 */
    uint64_t imu_noise_state;          /* its own stream, so the older sensors' noise is unchanged */

    int64_t last_stimulus_seq;
    int nstimuli;                      /* the stimulus table as last taken from the block */
    int64_t stimulus_kind[ROQ_MAX_STIMULI], stimulus_first[ROQ_MAX_STIMULI], stimulus_end[ROQ_MAX_STIMULI];
    double stimulus_value[ROQ_MAX_STIMULI][3];

    double target[ROQ_JOINTS];
    double wheel_target[ROQ_LEGS];
    int64_t last_command_seq;
    int64_t tick;
    int64_t snapshot_seq;
    int64_t depth_frames;
    int applied_slot;                  /* the ring slot written this tick, for publish to copy; -1 none */
    int histogram_bin;                 /* the latency bin counted this tick, for publish to copy; -1 none */
    uint64_t noise_state;

    unsigned char *block;              /* Java's direct buffer */
    unsigned char *stage;              /* same layout; the tick writes here, publish copies under the seqlock */

    pthread_t thread;
    int thread_started;
    volatile int running;
    int dma_fd;
    int64_t period_ns;
} roq_sim;

/* roq_tick.c */
roq_sim *roq_open(const char *mjcf, const float *heights, int nheights, const double *fragile, int nfragile,
                  const double *params, unsigned char *block, char *error, int error_size);
void roq_tick(roq_sim *s);
void roq_close(roq_sim *s);
uint64_t roq_state_hash(const roq_sim *s);
int64_t roq_bare_step_nanos(roq_sim *s, int ticks);

/* roq_ray.c: distance along the unit vector vec to the ground (terrain, intact fragile cells), or -1 */
double roq_ground_ray(const roq_sim *s, const mjtNum pnt[3], const mjtNum vec[3], double max_range);

/* roq_loop.c */
int roq_start(roq_sim *s, int priority, char *warnings, int warnings_size);
void roq_stop(roq_sim *s);
void roq_record_latency(roq_sim *s, int64_t latency_ns);

/* block access */
#define BLK_D(b, off) ((double *)((b) + (off)))
#define BLK_F(b, off) ((float *)((b) + (off)))
#define BLK_L(b, off) ((int64_t *)((b) + (off)))
#define BLK_I(b, off) ((int32_t *)((b) + (off)))

#endif
