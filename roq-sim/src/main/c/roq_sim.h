/*
 * The joint loop in MuJoCo's shape: a roq_model (roq_model.h, constant while running but for the one documented
 * edit), a roq_state (roq_state.h), the real-time thread apart (roq_loop.h). No globals: every function takes
 * them explicitly. The tick allocates nothing, prints nothing, takes no lock and makes no system call.
 */
#ifndef ROQ_SIM_H
#define ROQ_SIM_H

#include "roq_model.h"
#include "roq_state.h"

/* roq_tick.c */
/* Sizes and fills the state for the model: the robot in its initial pose, the first snapshot published into
   block (ROQ_BLOCK_SIZE bytes). NULL on failure, with what failed in error. */
roq_state *roq_state_open(const roq_model *model, unsigned char *block, char *error, int error_size);
void roq_state_close(roq_state *state);
/* One tick: command, stimuli, the model edits (the safe point), mj_step1, sensors, servos, mj_step2, contact
   forces and fragile cells, publish. */
void roq_tick(roq_model *model, roq_state *state);
uint64_t roq_state_hash(const roq_model *model, const roq_state *state);
/* A bare mj_step loop on a copy of the data, nanoseconds; -1 when the copy cannot be allocated. */
int64_t roq_bare_step_nanos(const roq_model *model, const roq_state *state, int ticks);

/* roq_ray.c: distance along the unit vector vec to the ground (terrain, intact fragile cells), or -1 */
double roq_ground_ray(const roq_model *model, const roq_state *state, const mjtNum pnt[3], const mjtNum vec[3],
                      double max_range);

#endif
