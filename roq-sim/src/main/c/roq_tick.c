/*
 * One tick of the simulated RoQ: command slot -> 12 servos (PD through a DC motor's current and voltage limits)
 * -> mj_step -> sensors -> fragile cells -> seqlock publish. Used by the real-time thread and by stepped mode.
 * Every function takes the model (const, but for the one edit at the safe point) and the state explicitly.
 * No allocation, print, lock or system call in roq_tick.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "roq_sim.h"

static double clampd(double v, double lo, double hi) {
    return v < lo ? lo : (v > hi ? hi : v);
}

/* xorshift64*: seeded, reproducible noise in [-1, 1). */
static double noise_from(uint64_t *stream) {
    uint64_t x = *stream;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    *stream = x;
    return ((double)((x * 2685821657736338717ULL) >> 11) / 9007199254740992.0) * 2.0 - 1.0;
}

static double noisy(const roq_model *model, roq_state *s, double v, double amplitude) {
    return model->params.noise ? v + amplitude * noise_from(&s->noise_state) : v;
}

/* IMU noise: its own stream, so adding the IMU left every older sensor's noise as it was. */
static double imu_noisy(const roq_model *model, roq_state *s, double v, double amplitude) {
    return model->params.noise ? v + amplitude * noise_from(&s->imu_noise_state) : v;
}

static double joint_min(const roq_model *model, int j) { return model->params.joint.min[j % ROQ_JOINTS_PER_LEG]; }
static double joint_max(const roq_model *model, int j) { return model->params.joint.max[j % ROQ_JOINTS_PER_LEG]; }

/* Takes a new, complete, fresh command from the slot; bad values are clamped or ignored and counted. */
static void take_command(const roq_model *model, roq_state *s) {
    unsigned char *b = s->block;
    unsigned char *st = s->stage;
    int64_t before = __atomic_load_n(BLK_L(b, COMMAND_SEQ), __ATOMIC_ACQUIRE);
    if (before == s->last_command_seq || (before & 1)) {
        return;
    }
    double targets[ROQ_JOINTS], wheels[ROQ_LEGS];
    int64_t issued = *(volatile int64_t *)BLK_L(b, C_ISSUED_TICK);
    int64_t flags = *(volatile int64_t *)BLK_L(b, C_FLAGS);
    int64_t source = *(volatile int64_t *)BLK_L(b, C_SOURCE_TICK);
    memcpy(targets, b + C_TARGETS, sizeof targets);
    memcpy(wheels, b + C_WHEEL_SPEED, sizeof wheels);
    __atomic_thread_fence(__ATOMIC_ACQUIRE);
    if (__atomic_load_n(BLK_L(b, COMMAND_SEQ), __ATOMIC_RELAXED) != before) {
        return; /* Java was writing: take it next tick */
    }
    s->last_command_seq = before;
    if (s->tick - issued > ROQ_STALE_TICKS) {
        (*BLK_L(st, T_COMMANDS_STALE))++;
        return;
    }
    for (int j = 0; j < ROQ_JOINTS; j++) {
        double v = targets[j];
        if (!isfinite(v)) {
            (*BLK_L(st, T_COMMANDS_NAN))++;
            continue;
        }
        if (v < joint_min(model, j) || v > joint_max(model, j)) {
            (*BLK_L(st, T_COMMANDS_OUT_OF_RANGE))++;
            v = clampd(v, joint_min(model, j), joint_max(model, j));
        }
        s->target[j] = v;
    }
    double vmax = model->params.wheel.max_speed;
    for (int i = 0; i < ROQ_LEGS; i++) {
        double v = (flags & FLAG_WHEELS) ? wheels[i] : 0.0;
        if (!isfinite(v)) {
            (*BLK_L(st, T_COMMANDS_NAN))++;
            v = 0.0;
        } else if (v < -vmax || v > vmax) {
            (*BLK_L(st, T_COMMANDS_OUT_OF_RANGE))++;
            v = clampd(v, -vmax, vmax);
        }
        s->wheel_target[i] = v;
    }
    int64_t n = ++(*BLK_L(st, T_COMMANDS_APPLIED));
    /* reflex latency: applied now, the command first shows in snapshot tick + 1; a command computed from no
       snapshot (source 0) has none */
    source = source < 0 ? issued : source;
    *BLK_L(st, T_LAST_APPLIED_TICK) = s->tick;
    *BLK_L(st, T_LAST_APPLIED_BASED_ON) = source;
    s->applied_slot = (int)((n - 1) % ROQ_APPLIED_RING);
    BLK_L(st, A_RING + A_ENTRY_SIZE * s->applied_slot)[0] = s->tick;
    BLK_L(st, A_RING + A_ENTRY_SIZE * s->applied_slot)[1] = source;
    if (source > 0) {
        int64_t reflex = s->tick + 1 - source;
        BLK_I(st, T_REFLEX_HISTOGRAM)[reflex < 0 ? 0 : (reflex >= ROQ_REFLEX_BINS ? ROQ_REFLEX_BINS - 1 : reflex)]++;
    }
}

/* Takes a new, complete stimulus table from the block (same protocol as the command slot). */
static void take_stimuli(roq_state *s) {
    unsigned char *b = s->block;
    int64_t before = __atomic_load_n(BLK_L(b, STIMULUS_SEQ), __ATOMIC_ACQUIRE);
    if (before == s->last_stimulus_seq || (before & 1)) {
        return;
    }
    int64_t n = *(volatile int64_t *)BLK_L(b, X_COUNT);
    n = n < 0 ? 0 : (n > ROQ_MAX_STIMULI ? ROQ_MAX_STIMULI : n);
    roq_stimulus table[ROQ_MAX_STIMULI];
    for (int i = 0; i < n; i++) {
        const unsigned char *e = b + X_TABLE + X_ENTRY_SIZE * i;
        table[i].kind = ((volatile const int64_t *)e)[0];
        table[i].first = ((volatile const int64_t *)e)[1];
        table[i].end = ((volatile const int64_t *)e)[2];
        memcpy(table[i].value, e + 24, sizeof table[i].value);
    }
    __atomic_thread_fence(__ATOMIC_ACQUIRE);
    if (__atomic_load_n(BLK_L(b, STIMULUS_SEQ), __ATOMIC_RELAXED) != before) {
        return; /* Java was writing: take it next tick */
    }
    s->last_stimulus_seq = before;
    s->nstimuli = (int)n;
    memcpy(s->stimulus, table, sizeof(roq_stimulus) * (size_t)n);
}

/*
 * Fragile cell i breaks: the state records it at once (the snapshot's mask and count, the rays skip it) and
 * queues the model edit — dropping the cell out of the way — for roq_model_apply_edits at the next safe point.
 */
static void break_cell(roq_state *s, int i) {
    s->cell[i].broken = 1;
    s->broken_count++;
    s->pending_break[s->npending_breaks++] = i;
    BLK_L(s->stage, S_BROKEN_MASK)[i >> 6] |= (int64_t)(1ULL << (i & 63));
}

/*
 * Stimuli of this tick: the pushes active now add up to one force on the body's centre of mass
 * (d->xfrc_applied, read by mj_step2), and a cell due to break now breaks whatever stands on it.
 */
static void apply_stimuli(const roq_model *model, roq_state *s) {
    double f[3] = {0, 0, 0};
    for (int i = 0; i < s->nstimuli; i++) {
        const roq_stimulus *x = &s->stimulus[i];
        if (s->tick < x->first || s->tick >= x->end) {
            continue;
        }
        if (x->kind == X_KIND_PUSH) {
            for (int r = 0; r < 3; r++) {
                f[r] += x->value[r];
            }
        } else if (x->kind == X_KIND_BREAK && s->tick == x->first) {
            int cell = (int)x->value[0];
            if (cell >= 0 && cell < model->nfragile && !s->cell[cell].broken) {
                break_cell(s, cell);
            }
        }
    }
    mjtNum *xfrc = s->d->xfrc_applied + 6 * model->body_id;
    for (int r = 0; r < 3; r++) {
        xfrc[r] = f[r];
        xfrc[r + 3] = 0;
        BLK_D(s->stage, S_PUSH_FORCE)[r] = f[r];
    }
}

/*
 * Servo: PD on the joint target gives the wanted torque; the DC motor can deliver at most its current limit, and
 * the supply voltage minus the back-EMF bounds the current in either direction (the torque-speed line). Coulomb
 * and viscous friction and the rotor's reflected inertia are the joint's frictionloss, damping and armature in
 * the model.
 */
static void servos(const roq_model *model, roq_state *s) {
    const roq_servo_params *sv = &model->params.servo;
    const roq_wheel_params *wh = &model->params.wheel;
    double k = sv->torque_constant * sv->gear;               /* N·m/A and V·s/rad at the joint */
    double per_amp = k * sv->efficiency;
    double max_current_torque = per_amp * sv->current_limit;
    for (int j = 0; j < ROQ_JOINTS; j++) {
        double q = s->d->qpos[model->qadr[j]];
        double qd = s->d->qvel[model->dadr[j]];
        double wanted = sv->kp * (s->target[j] - q) - sv->kd * qd;
        double hi = per_amp * (sv->supply_voltage - k * qd) / sv->resistance;
        double lo = per_amp * (-sv->supply_voltage - k * qd) / sv->resistance;
        hi = fmax(fmin(hi, max_current_torque), -max_current_torque);
        lo = fmin(fmax(lo, -max_current_torque), max_current_torque);
        double tau = clampd(wanted, lo, hi);
        s->d->qfrc_applied[model->dadr[j]] = tau;
        BLK_D(s->stage, S_JOINT_TORQUE)[j] = tau;
    }
    for (int i = 0; i < ROQ_LEGS; i++) {
        double w = s->d->qvel[model->wheel_dadr[i]];
        s->d->qfrc_applied[model->wheel_dadr[i]] =
            clampd(wh->kv * (s->wheel_target[i] - w), -wh->max_torque, wh->max_torque);
    }
}

/* A ray from body-frame point `at` along body-frame unit direction `dir` at the ground (terrain, fragile cells). */
static double ray(const roq_model *model, const roq_state *s, const double at[3], const double dir[3],
                  double max_range) {
    const mjtNum *pos = s->d->xpos + 3 * model->body_id;
    const mjtNum *mat = s->d->xmat + 9 * model->body_id;
    mjtNum pnt[3], vec[3];
    for (int r = 0; r < 3; r++) {
        pnt[r] = pos[r] + mat[3 * r] * at[0] + mat[3 * r + 1] * at[1] + mat[3 * r + 2] * at[2];
        vec[r] = mat[3 * r] * dir[0] + mat[3 * r + 1] * dir[1] + mat[3 * r + 2] * dir[2];
    }
    mjtNum dist = roq_ground_ray(model, s, pnt, vec, max_range);
    return dist < 0 ? max_range : dist;
}

static void direction(double pitch_down, double yaw_left, double out[3]) {
    out[0] = cos(pitch_down) * cos(yaw_left);
    out[1] = cos(pitch_down) * sin(yaw_left);
    out[2] = -sin(pitch_down);
}

/* The range sensors: they refresh at their own rates (rays are the tick's dearest part); between refreshes the
   snapshot keeps their last reading. */
static void range_sensors(const roq_model *model, roq_state *s) {
    const roq_params *p = &model->params;
    unsigned char *st = s->stage;
    double dir[3];
    if (s->tick % p->ir_period == 0) {
        direction(p->ir.angle, 0, dir);
        BLK_D(st, S_IR_RANGE)[0] = noisy(model, s, ray(model, s, p->ir.position, dir, p->ir.max_range), 0.005);
    }
    if (s->tick % p->ultrasonic_period == 0) {
        double nearest = p->ultrasonic.max_range;
        for (int k = -1; k <= 1; k++) {
            direction(0, k * p->ultrasonic.angle, dir); /* the cone's half angle, swept in yaw */
            nearest = fmin(nearest, ray(model, s, p->ultrasonic.position, dir, p->ultrasonic.max_range));
        }
        BLK_D(st, S_ULTRASONIC_RANGE)[0] = noisy(model, s, nearest, 0.005);
    }
    /* The depth image, spread evenly: ROQ_DEPTH_WIDTH / depth_row_period pixels every tick, a frame every
       depth_row_period × ROQ_DEPTH_HEIGHT ticks. Spread, because one long ray over a tall heightfield can cost
       30 µs in MuJoCo 2.2.2: a whole row in one tick overran the 1 ms period on the slope course. */
    const roq_camera_params *cam = &p->camera;
    int64_t period = p->depth_row_period;
    int per_tick = ROQ_DEPTH_WIDTH / (int)period;
    int first = (int)(s->tick % (period * ROQ_DEPTH_HEIGHT)) * per_tick;
    for (int k = first; k < first + per_tick; k++) {
        int row = k / ROQ_DEPTH_WIDTH, c = k % ROQ_DEPTH_WIDTH;
        double pitch = cam->pitch_down + ((row + 0.5) / ROQ_DEPTH_HEIGHT - 0.5) * cam->fov_y;
        double yaw = -((c + 0.5) / ROQ_DEPTH_WIDTH - 0.5) * cam->fov_x;
        direction(pitch, yaw, dir);
        BLK_F(st, S_DEPTH)[k] = (float)ray(model, s, cam->position, dir, cam->max_range);
    }
    if (first + per_tick == ROQ_DEPTH_WIDTH * ROQ_DEPTH_HEIGHT) {
        s->depth_frames++;
    }
}

/* Sensors that read the state at the start of the tick (after mj_step1: kinematics and contacts are current). */
static void state_sensors(const roq_model *model, roq_state *s) {
    unsigned char *st = s->stage;
    const mjData *d = s->d;
    for (int j = 0; j < ROQ_JOINTS; j++) {
        BLK_D(st, S_JOINT_ANGLE)[j] = noisy(model, s, d->qpos[model->qadr[j]], 0.0005);
        BLK_D(st, S_JOINT_VELOCITY)[j] = noisy(model, s, d->qvel[model->dadr[j]], 0.005);
    }
    for (int i = 0; i < ROQ_LEGS; i++) {
        BLK_D(st, S_WHEEL_SPEED)[i] = d->qvel[model->wheel_dadr[i]];
    }
    const mjtNum *q = d->qpos + 3; /* the free joint's quaternion w x y z */
    double roll = atan2(2 * (q[0] * q[1] + q[2] * q[3]), 1 - 2 * (q[1] * q[1] + q[2] * q[2]));
    double sp = clampd(2 * (q[0] * q[2] - q[3] * q[1]), -1, 1);
    BLK_D(st, S_ROLL)[0] = noisy(model, s, roll, 0.002);
    BLK_D(st, S_PITCH)[0] = noisy(model, s, asin(sp), 0.002);
    for (int r = 0; r < 3; r++) {
        BLK_D(st, S_BODY_POSITION)[r] = d->qpos[r];
        BLK_D(st, S_CENTRE_OF_MASS)[r] = d->subtree_com[3 * model->body_id + r];
    }
    for (int r = 0; r < 4; r++) {
        BLK_D(st, S_BODY_QUATERNION)[r] = q[r];
    }
    for (int r = 0; r < 3; r++) { /* gyro: mj_step1 computed the velocity sensors */
        BLK_D(st, S_GYRO)[r] = imu_noisy(model, s, d->sensordata[model->gyro_adr + r] + s->imu_bias[r], 0.005);
    }
    if (model->params.range_sensors) {
        range_sensors(model, s);
    }
}

/* Contact forces of the step just taken (mj_step2 solved them): soles and fragile cells; a cell held over its
   strength long enough breaks. */
static void force_sensors(const roq_model *model, roq_state *s) {
    double foot[ROQ_LEGS] = {0, 0, 0, 0};
    for (int i = 0; i < model->nfragile; i++) {
        s->cell[i].load = 0;
    }
    for (int c = 0; c < s->d->ncon; c++) {
        const mjContact *con = s->d->contact + c;
        int r1 = model->geom_role[con->geom1], r2 = model->geom_role[con->geom2];
        if (r1 < 0 && r2 < 0) {
            continue;
        }
        mjtNum f[6];
        mj_contactForce(model->m, s->d, c, f);
        for (int k = 0; k < 2; k++) {
            int role = k == 0 ? r1 : r2;
            if (role >= ROQ_GEOM_ROLE_CELL) {
                s->cell[role - ROQ_GEOM_ROLE_CELL].load += f[0];
            } else if (role >= 0) {
                foot[role] += f[0];
            }
        }
    }
    for (int i = 0; i < ROQ_LEGS; i++) {
        BLK_D(s->stage, S_FOOT_FORCE)[i] = noisy(model, s, foot[i], 0.5);
    }
    for (int r = 0; r < 3; r++) { /* accelerometer: mj_step2 computed the acceleration sensors */
        BLK_D(s->stage, S_ACCEL)[r] =
            imu_noisy(model, s, s->d->sensordata[model->accel_adr + r] + s->imu_bias[3 + r], 0.05);
    }
    for (int i = 0; i < model->nfragile; i++) {
        roq_cell_state *cell = &s->cell[i];
        if (cell->broken) {
            continue;
        }
        cell->load_ticks = cell->load > model->fragile[i].strength ? cell->load_ticks + 1 : 0;
        if (cell->load_ticks >= model->params.break_hold_ticks) {
            break_cell(s, i);
        }
    }
    *BLK_L(s->stage, S_BROKEN_COUNT) = s->broken_count;
}

/* Seqlock publish: odd while copying the stage's snapshot and statistics into the shared block. */
static void publish(roq_state *s) {
    int64_t *seq = BLK_L(s->block, SNAPSHOT_SEQ);
    __atomic_store_n(seq, s->snapshot_seq + 1, __ATOMIC_RELAXED);
    __atomic_thread_fence(__ATOMIC_RELEASE);
    /* the snapshot, the statistics' counters, and of the histogram only the bin this tick counted */
    memcpy(s->block + S_TICK, s->stage + S_TICK, S_END - S_TICK);
    memcpy(s->block + T_TICKS, s->stage + T_TICKS, T_HISTOGRAM - T_TICKS);
    if (s->histogram_bin >= 0) {
        BLK_I(s->block, T_HISTOGRAM)[s->histogram_bin] = BLK_I(s->stage, T_HISTOGRAM)[s->histogram_bin];
        s->histogram_bin = -1;
    }
    memcpy(s->block + T_REFLEX_HISTOGRAM, s->stage + T_REFLEX_HISTOGRAM, 4 * ROQ_REFLEX_BINS);
    if (s->applied_slot >= 0) {
        memcpy(s->block + A_RING + A_ENTRY_SIZE * s->applied_slot, s->stage + A_RING + A_ENTRY_SIZE * s->applied_slot,
               A_ENTRY_SIZE);
        s->applied_slot = -1;
    }
    s->snapshot_seq += 2;
    __atomic_store_n(seq, s->snapshot_seq, __ATOMIC_RELEASE);
}

void roq_tick(roq_model *model, roq_state *s) {
    take_command(model, s);
    take_stimuli(s);
    apply_stimuli(model, s);
    /* The safe point: no step in progress; the cells broken since the last one (by the previous tick's loads or
       by this tick's stimuli) leave the model before mj_step1 reads it. The tick's only write to the model. */
    roq_model_apply_edits(model, s);
    mj_step1(model->m, s->d); /* from here on the model is only read */
    state_sensors(model, s);
    servos(model, s);
    mj_step2(model->m, s->d);
    force_sensors(model, s);
    s->tick++;
    *BLK_L(s->stage, S_TICK) = s->tick;
    *BLK_D(s->stage, S_TIME) = s->d->time;
    *BLK_L(s->stage, S_DEPTH_FRAMES) = s->depth_frames;
    *BLK_L(s->stage, T_TICKS) = s->tick;
    publish(s);
}

/* ---- open / close (not real-time: may allocate and report) ---------------------------------------------- */

static roq_state *fail(roq_state *s, char *error, int size, const char *message) {
    snprintf(error, size, "%s", message);
    roq_state_close(s);
    return NULL;
}

/* The noise streams from the seed, and the IMU's bias (drawn from its stream, fixed for the run). */
static void seed_noise(const roq_model *model, roq_state *s) {
    uint64_t seed = (uint64_t)model->params.noise_seed;
    s->noise_state = seed * 0x9E3779B97F4A7C15ULL + 0x2545F4914F6CDD1DULL;
    if (s->noise_state == 0) {
        s->noise_state = 1;
    }
    s->imu_noise_state = (seed + 1) * 0xD1B54A32D192ED03ULL + 0x8BB84B93962EACC9ULL;
    if (s->imu_noise_state == 0) {
        s->imu_noise_state = 1;
    }
    if (model->params.noise) { /* a bias per axis: gyro up to ±0.01 rad/s, accelerometer ±0.1 m/s^2 */
        for (int r = 0; r < 6; r++) {
            s->imu_bias[r] = (r < 3 ? 0.01 : 0.1) * noise_from(&s->imu_noise_state);
        }
    }
}

roq_state *roq_state_open(const roq_model *model, unsigned char *block, char *error, int error_size) {
    char msg[200];
    roq_state *s = calloc(1, sizeof(roq_state));
    if (s == NULL) {
        snprintf(error, error_size, "out of memory for roq_state (%zu bytes)", sizeof(roq_state));
        return NULL;
    }
    s->histogram_bin = -1;
    s->applied_slot = -1;
    s->block = block;
    s->stage = calloc(1, ROQ_BLOCK_SIZE);
    if (s->stage == NULL) {
        snprintf(msg, sizeof msg, "out of memory for the stage block (%d bytes)", ROQ_BLOCK_SIZE);
        return fail(s, error, error_size, msg);
    }
    s->d = mj_makeData(model->m);
    if (s->d == NULL) {
        return fail(s, error, error_size, "MuJoCo could not allocate mjData for the model");
    }
    for (int j = 0; j < ROQ_JOINTS; j++) {
        s->target[j] = model->params.joint.initial[j % ROQ_JOINTS_PER_LEG];
        s->d->qpos[model->qadr[j]] = s->target[j];
    }
    seed_noise(model, s);
    memset(block, 0, ROQ_BLOCK_SIZE);
    *BLK_I(block, LAYOUT_VERSION) = ROQ_VERSION;
    mj_forward(model->m, s->d);
    for (int r = 0; r < 3; r++) {
        BLK_D(s->stage, S_ACCEL)[r] = s->d->sensordata[model->accel_adr + r] + s->imu_bias[3 + r];
    }
    int64_t period = model->params.depth_row_period;
    /* a whole first image, so readers never see an empty one */
    for (int64_t t = 0; t < period * ROQ_DEPTH_HEIGHT; t++) {
        s->tick = t;
        state_sensors(model, s);
    }
    s->tick = 0;
    s->depth_frames = 1;
    if (!model->params.range_sensors) {
        BLK_D(s->stage, S_IR_RANGE)[0] = NAN;
        BLK_D(s->stage, S_ULTRASONIC_RANGE)[0] = NAN;
        for (int i = 0; i < ROQ_DEPTH_WIDTH * ROQ_DEPTH_HEIGHT; i++) {
            BLK_F(s->stage, S_DEPTH)[i] = NAN;
        }
        s->depth_frames = 0;
    }
    *BLK_L(s->stage, S_DEPTH_FRAMES) = s->depth_frames;
    publish(s);
    return s;
}

void roq_state_close(roq_state *s) {
    if (s == NULL) {
        return;
    }
    if (s->d) {
        mj_deleteData(s->d);
    }
    free(s->stage);
    free(s);
}

uint64_t roq_state_hash(const roq_model *model, const roq_state *s) {
    uint64_t h = 1469598103934665603ULL;
#define HASH_BYTES(ptr, n)                                      \
    do {                                                        \
        const unsigned char *b_ = (const unsigned char *)(ptr); \
        for (size_t i_ = 0; i_ < (size_t)(n); i_++) {           \
            h ^= b_[i_];                                        \
            h *= 1099511628211ULL;                              \
        }                                                       \
    } while (0)
    HASH_BYTES(&s->d->time, sizeof(mjtNum));
    HASH_BYTES(s->d->qpos, sizeof(mjtNum) * model->m->nq);
    HASH_BYTES(s->d->qvel, sizeof(mjtNum) * model->m->nv);
    HASH_BYTES(s->d->qacc, sizeof(mjtNum) * model->m->nv);
    for (int i = 0; i < model->nfragile; i++) {
        HASH_BYTES(&s->cell[i].broken, 1);
    }
#undef HASH_BYTES
    return h;
}

int64_t roq_bare_step_nanos(const roq_model *model, const roq_state *s, int ticks) {
    mjData *d = mj_makeData(model->m);
    if (d == NULL) {
        return -1;
    }
    mj_copyData(d, model->m, s->d);
    struct timespec a, b;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (int i = 0; i < ticks; i++) {
        mj_step(model->m, d);
    }
    clock_gettime(CLOCK_MONOTONIC, &b);
    mj_deleteData(d);
    return (int64_t)(b.tv_sec - a.tv_sec) * 1000000000LL + (b.tv_nsec - a.tv_nsec);
}
