/*
 * One tick of the simulated RoQ: command slot -> 12 servos (PD through a DC motor's current and voltage limits)
 * -> mj_step -> sensors -> fragile cells -> seqlock publish. Used by the real-time thread and by stepped mode.
 * No allocation, print, lock or system call in roq_tick.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "roq_sim.h"

#define JOINTS_PER_LEG 3
#define JOINT_QPOS_FIRST 1 /* joint 0 is the free joint; then per leg yaw, lift, knee, wheel */

static double clampd(double v, double lo, double hi) {
    return v < lo ? lo : (v > hi ? hi : v);
}

/* xorshift64*: seeded, reproducible noise in [-1, 1). */
static double noise_from(uint64_t *state) {
    uint64_t x = *state;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    *state = x;
    return ((double)((x * 2685821657736338717ULL) >> 11) / 9007199254740992.0) * 2.0 - 1.0;
}

static double noisy(roq_sim *s, double v, double amplitude) {
    return s->p[P_NOISE] != 0 ? v + amplitude * noise_from(&s->noise_state) : v;
}

/* IMU noise: its own stream, so adding the IMU left every older sensor's noise as it was. */
static double imu_noisy(roq_sim *s, double v, double amplitude) {
    return s->p[P_NOISE] != 0 ? v + amplitude * noise_from(&s->imu_noise_state) : v;
}

static double joint_min(const roq_sim *s, int j) { return s->p[P_JOINT_MIN_0 + j % JOINTS_PER_LEG]; }
static double joint_max(const roq_sim *s, int j) { return s->p[P_JOINT_MAX_0 + j % JOINTS_PER_LEG]; }

/* Takes a new, complete, fresh command from the slot; bad values are clamped or ignored and counted. */
static void take_command(roq_sim *s) {
    unsigned char *b = s->block;
    unsigned char *st = s->stage;
    int64_t before = __atomic_load_n(BLK_L(b, L_COMMAND_SEQ), __ATOMIC_ACQUIRE);
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
    if (__atomic_load_n(BLK_L(b, L_COMMAND_SEQ), __ATOMIC_RELAXED) != before) {
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
        if (v < joint_min(s, j) || v > joint_max(s, j)) {
            (*BLK_L(st, T_COMMANDS_OUT_OF_RANGE))++;
            v = clampd(v, joint_min(s, j), joint_max(s, j));
        }
        s->target[j] = v;
    }
    double vmax = s->p[P_WHEEL_SPEED];
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
static void take_stimuli(roq_sim *s) {
    unsigned char *b = s->block;
    int64_t before = __atomic_load_n(BLK_L(b, L_STIMULUS_SEQ), __ATOMIC_ACQUIRE);
    if (before == s->last_stimulus_seq || (before & 1)) {
        return;
    }
    int64_t n = *(volatile int64_t *)BLK_L(b, X_COUNT);
    n = n < 0 ? 0 : (n > ROQ_MAX_STIMULI ? ROQ_MAX_STIMULI : n);
    int64_t kind[ROQ_MAX_STIMULI], first[ROQ_MAX_STIMULI], end[ROQ_MAX_STIMULI];
    double value[ROQ_MAX_STIMULI][3];
    for (int i = 0; i < n; i++) {
        const unsigned char *e = b + X_TABLE + X_ENTRY_SIZE * i;
        kind[i] = ((volatile const int64_t *)e)[0];
        first[i] = ((volatile const int64_t *)e)[1];
        end[i] = ((volatile const int64_t *)e)[2];
        memcpy(value[i], e + 24, sizeof value[i]);
    }
    __atomic_thread_fence(__ATOMIC_ACQUIRE);
    if (__atomic_load_n(BLK_L(b, L_STIMULUS_SEQ), __ATOMIC_RELAXED) != before) {
        return; /* Java was writing: take it next tick */
    }
    s->last_stimulus_seq = before;
    s->nstimuli = (int)n;
    memcpy(s->stimulus_kind, kind, sizeof(int64_t) * (size_t)n);
    memcpy(s->stimulus_first, first, sizeof(int64_t) * (size_t)n);
    memcpy(s->stimulus_end, end, sizeof(int64_t) * (size_t)n);
    memcpy(s->stimulus_value, value, sizeof(double) * 3 * (size_t)n);
}

static void break_cell(roq_sim *s, int i);

/*
 * Stimuli of this tick: the pushes active now add up to one force on the body's centre of mass
 * (d->xfrc_applied, read by mj_step2), and a cell due to break now breaks whatever stands on it.
 */
static void apply_stimuli(roq_sim *s) {
    double f[3] = {0, 0, 0};
    for (int i = 0; i < s->nstimuli; i++) {
        if (s->tick < s->stimulus_first[i] || s->tick >= s->stimulus_end[i]) {
            continue;
        }
        if (s->stimulus_kind[i] == X_KIND_PUSH) {
            for (int r = 0; r < 3; r++) {
                f[r] += s->stimulus_value[i][r];
            }
        } else if (s->stimulus_kind[i] == X_KIND_BREAK && s->tick == s->stimulus_first[i]) {
            int cell = (int)s->stimulus_value[i][0];
            if (cell >= 0 && cell < s->nfragile && !s->fragile_broken[cell]) {
                break_cell(s, cell);
            }
        }
    }
    mjtNum *x = s->d->xfrc_applied + 6 * s->body_id;
    for (int r = 0; r < 3; r++) {
        x[r] = f[r];
        x[r + 3] = 0;
        BLK_D(s->stage, S_PUSH_FORCE)[r] = f[r];
    }
}

/*
 * Servo: PD on the joint target gives the wanted torque; the DC motor can deliver at most its current limit, and
 * the supply voltage minus the back-EMF bounds the current in either direction (the torque-speed line). Coulomb
 * and viscous friction and the rotor's reflected inertia are the joint's frictionloss, damping and armature in
 * the model.
 */
static void servos(roq_sim *s) {
    const double *p = s->p;
    double k = p[P_TORQUE_CONSTANT] * p[P_GEAR];             /* N·m/A and V·s/rad at the joint */
    double per_amp = k * p[P_EFFICIENCY];
    double max_current_torque = per_amp * p[P_CURRENT_LIMIT];
    for (int j = 0; j < ROQ_JOINTS; j++) {
        double q = s->d->qpos[s->qadr[j]];
        double qd = s->d->qvel[s->dadr[j]];
        double wanted = p[P_KP] * (s->target[j] - q) - p[P_KD] * qd;
        double hi = per_amp * (p[P_SUPPLY_VOLTAGE] - k * qd) / p[P_RESISTANCE];
        double lo = per_amp * (-p[P_SUPPLY_VOLTAGE] - k * qd) / p[P_RESISTANCE];
        hi = fmax(fmin(hi, max_current_torque), -max_current_torque);
        lo = fmin(fmax(lo, -max_current_torque), max_current_torque);
        double tau = clampd(wanted, lo, hi);
        s->d->qfrc_applied[s->dadr[j]] = tau;
        BLK_D(s->stage, S_JOINT_TORQUE)[j] = tau;
    }
    for (int i = 0; i < ROQ_LEGS; i++) {
        double w = s->d->qvel[s->wheel_dadr[i]];
        s->d->qfrc_applied[s->wheel_dadr[i]] =
            clampd(p[P_WHEEL_KV] * (s->wheel_target[i] - w), -p[P_WHEEL_TORQUE], p[P_WHEEL_TORQUE]);
    }
}

/* A ray from body-frame point `at` along body-frame unit direction `dir` at the ground (terrain, fragile cells). */
static double ray(const roq_sim *s, const double at[3], const double dir[3], double max_range) {
    const mjtNum *pos = s->d->xpos + 3 * s->body_id;
    const mjtNum *mat = s->d->xmat + 9 * s->body_id;
    mjtNum pnt[3], vec[3];
    for (int r = 0; r < 3; r++) {
        pnt[r] = pos[r] + mat[3 * r] * at[0] + mat[3 * r + 1] * at[1] + mat[3 * r + 2] * at[2];
        vec[r] = mat[3 * r] * dir[0] + mat[3 * r + 1] * dir[1] + mat[3 * r + 2] * dir[2];
    }
    mjtNum dist = roq_ground_ray(s, pnt, vec, max_range);
    return dist < 0 ? max_range : dist;
}

static void direction(double pitch_down, double yaw_left, double out[3]) {
    out[0] = cos(pitch_down) * cos(yaw_left);
    out[1] = cos(pitch_down) * sin(yaw_left);
    out[2] = -sin(pitch_down);
}

/* Sensors that read the state at the start of the tick (after mj_step1: kinematics and contacts are current). */
static void state_sensors(roq_sim *s) {
    unsigned char *st = s->stage;
    const mjData *d = s->d;
    const double *p = s->p;
    for (int j = 0; j < ROQ_JOINTS; j++) {
        BLK_D(st, S_JOINT_ANGLE)[j] = noisy(s, d->qpos[s->qadr[j]], 0.0005);
        BLK_D(st, S_JOINT_VELOCITY)[j] = noisy(s, d->qvel[s->dadr[j]], 0.005);
    }
    for (int i = 0; i < ROQ_LEGS; i++) {
        BLK_D(st, S_WHEEL_SPEED)[i] = d->qvel[s->wheel_dadr[i]];
    }
    const mjtNum *q = d->qpos + 3; /* the free joint's quaternion w x y z */
    double roll = atan2(2 * (q[0] * q[1] + q[2] * q[3]), 1 - 2 * (q[1] * q[1] + q[2] * q[2]));
    double sp = clampd(2 * (q[0] * q[2] - q[3] * q[1]), -1, 1);
    BLK_D(st, S_ROLL)[0] = noisy(s, roll, 0.002);
    BLK_D(st, S_PITCH)[0] = noisy(s, asin(sp), 0.002);
    for (int r = 0; r < 3; r++) {
        BLK_D(st, S_BODY_POSITION)[r] = d->qpos[r];
        BLK_D(st, S_CENTRE_OF_MASS)[r] = d->subtree_com[3 * s->body_id + r];
    }
    for (int r = 0; r < 4; r++) {
        BLK_D(st, S_BODY_QUATERNION)[r] = q[r];
    }
    for (int r = 0; r < 3; r++) { /* gyro: mj_step1 computed the velocity sensors */
        BLK_D(st, S_GYRO)[r] = imu_noisy(s, d->sensordata[s->gyro_adr + r] + s->imu_bias[r], 0.005);
    }

    /* Range sensors refresh at their own rates (rays are the tick's dearest part); between refreshes the
       snapshot keeps their last reading. */
    if (p[P_RANGE_SENSORS] == 0) {
        return;
    }
    double dir[3];
    if (s->tick % (int64_t)p[P_IR_PERIOD] == 0) {
        direction(p[P_IR_0 + 3], 0, dir);
        BLK_D(st, S_IR_RANGE)[0] = noisy(s, ray(s, p + P_IR_0, dir, p[P_IR_0 + 4]), 0.005);
    }
    if (s->tick % (int64_t)p[P_US_PERIOD] == 0) {
        double nearest = p[P_US_0 + 4];
        for (int k = -1; k <= 1; k++) {
            direction(0, k * p[P_US_0 + 3], dir);
            nearest = fmin(nearest, ray(s, p + P_US_0, dir, p[P_US_0 + 4]));
        }
        BLK_D(st, S_ULTRASONIC_RANGE)[0] = noisy(s, nearest, 0.005);
    }
    /* The depth image, spread evenly: ROQ_DEPTH_W / P_DEPTH_ROW_PERIOD pixels every tick, a frame every
       P_DEPTH_ROW_PERIOD × ROQ_DEPTH_H ticks. Spread, because one long ray over a tall heightfield can cost
       30 µs in MuJoCo 2.2.2: a whole row in one tick overran the 1 ms period on the slope course. */
    int64_t period = (int64_t)p[P_DEPTH_ROW_PERIOD];
    int per_tick = ROQ_DEPTH_W / (int)period;
    int first = (int)(s->tick % (period * ROQ_DEPTH_H)) * per_tick;
    for (int k = first; k < first + per_tick; k++) {
        int row = k / ROQ_DEPTH_W, c = k % ROQ_DEPTH_W;
        double pitch = p[P_CAMERA_0 + 3] + ((row + 0.5) / ROQ_DEPTH_H - 0.5) * p[P_CAMERA_0 + 5];
        double yaw = -((c + 0.5) / ROQ_DEPTH_W - 0.5) * p[P_CAMERA_0 + 4];
        direction(pitch, yaw, dir);
        BLK_F(st, S_DEPTH)[k] = (float)ray(s, p + P_CAMERA_0, dir, p[P_CAMERA_0 + 6]);
    }
    if (first + per_tick == ROQ_DEPTH_W * ROQ_DEPTH_H) {
        s->depth_frames++;
    }
}

static void break_cell(roq_sim *s, int i) {
    int g = s->fragile_geom[i];
    s->m->geom_contype[g] = 0;
    s->m->geom_conaffinity[g] = 0;
    s->m->geom_pos[3 * g + 2] -= s->fragile_height[i] + 0.02;
    s->fragile_broken[i] = 1;
    s->broken_count++;
    BLK_L(s->stage, S_BROKEN_MASK)[i >> 6] |= (int64_t)(1ULL << (i & 63));
}

/* Contact forces of the step just taken (mj_step2 solved them): soles and fragile cells. */
static void force_sensors(roq_sim *s) {
    double foot[ROQ_LEGS] = {0, 0, 0, 0};
    for (int i = 0; i < s->nfragile; i++) {
        s->fragile_load[i] = 0;
    }
    for (int c = 0; c < s->d->ncon; c++) {
        const mjContact *con = s->d->contact + c;
        int r1 = s->geom_role[con->geom1], r2 = s->geom_role[con->geom2];
        if (r1 < 0 && r2 < 0) {
            continue;
        }
        mjtNum f[6];
        mj_contactForce(s->m, s->d, c, f);
        for (int k = 0; k < 2; k++) {
            int role = k == 0 ? r1 : r2;
            if (role >= 100) {
                s->fragile_load[role - 100] += f[0];
            } else if (role >= 0) {
                foot[role] += f[0];
            }
        }
    }
    for (int i = 0; i < ROQ_LEGS; i++) {
        BLK_D(s->stage, S_FOOT_FORCE)[i] = noisy(s, foot[i], 0.5);
    }
    for (int r = 0; r < 3; r++) { /* accelerometer: mj_step2 computed the acceleration sensors */
        BLK_D(s->stage, S_ACCEL)[r] = imu_noisy(s, s->d->sensordata[s->accel_adr + r] + s->imu_bias[3 + r], 0.05);
    }
    int hold = (int)s->p[P_BREAK_HOLD_TICKS];
    for (int i = 0; i < s->nfragile; i++) {
        if (s->fragile_broken[i]) {
            continue;
        }
        s->fragile_load_ticks[i] = s->fragile_load[i] > s->fragile_strength[i] ? s->fragile_load_ticks[i] + 1 : 0;
        if (s->fragile_load_ticks[i] >= hold) {
            break_cell(s, i);
        }
    }
    *BLK_L(s->stage, S_BROKEN_COUNT) = s->broken_count;
}

/* Seqlock publish: odd while copying the stage's snapshot and statistics into the shared block. */
static void publish(roq_sim *s) {
    int64_t *seq = BLK_L(s->block, L_SNAPSHOT_SEQ);
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

void roq_tick(roq_sim *s) {
    take_command(s);
    take_stimuli(s);
    apply_stimuli(s);
    mj_step1(s->m, s->d);
    state_sensors(s);
    servos(s);
    mj_step2(s->m, s->d);
    force_sensors(s);
    s->tick++;
    *BLK_L(s->stage, S_TICK) = s->tick;
    *BLK_D(s->stage, S_TIME) = s->d->time;
    *BLK_L(s->stage, S_DEPTH_FRAMES) = s->depth_frames;
    *BLK_L(s->stage, T_TICKS) = s->tick;
    publish(s);
}

/* ---- open / close (not real-time: may allocate and report) ---------------------------------------------- */

static roq_sim *fail(roq_sim *s, char *error, int size, const char *message) {
    snprintf(error, size, "%s", message);
    roq_close(s);
    return NULL;
}

roq_sim *roq_open(const char *mjcf, const float *heights, int nheights, const double *fragile, int nfragile,
                  const double *params, unsigned char *block, char *error, int error_size) {
    char msg[1200];
    roq_sim *s = calloc(1, sizeof(roq_sim));
    if (s == NULL) {
        snprintf(error, error_size, "out of memory");
        return NULL;
    }
    s->dma_fd = -1;
    s->histogram_bin = -1;
    s->applied_slot = -1;
    memcpy(s->p, params, sizeof s->p);
    s->block = block;
    s->stage = calloc(1, ROQ_BLOCK_SIZE);
    char load_error[1000] = "";
    s->m = mj_loadXML(mjcf, NULL, load_error, sizeof load_error);
    if (s->m == NULL) {
        snprintf(msg, sizeof msg, "MuJoCo refused the model %s: %s", mjcf, load_error);
        return fail(s, error, error_size, msg);
    }
    if (s->m->nhfield != 1 || s->m->hfield_nrow[0] * s->m->hfield_ncol[0] != nheights) {
        snprintf(msg, sizeof msg, "model has %d heightfields of %d points, the course %d points",
                 s->m->nhfield, s->m->nhfield ? s->m->hfield_nrow[0] * s->m->hfield_ncol[0] : 0, nheights);
        return fail(s, error, error_size, msg);
    }
    for (int i = 0; i < nheights; i++) { /* Java scaled them to 0..1 of the elevation range */
        s->m->hfield_data[i] = heights[i];
    }
    if (s->m->njnt != 1 + ROQ_LEGS * 4 || s->m->jnt_type[0] != mjJNT_FREE) {
        snprintf(msg, sizeof msg, "model has %d joints, expected a free joint and %d leg joints", s->m->njnt,
                 ROQ_LEGS * 4);
        return fail(s, error, error_size, msg);
    }
    s->body_id = s->m->jnt_bodyid[0];
    s->terrain_geom = -1;
    for (int g = 0; g < s->m->ngeom; g++) {
        if (s->m->geom_type[g] == mjGEOM_HFIELD) {
            s->terrain_geom = g;
        }
    }
    if (s->terrain_geom < 0 || s->m->geom_bodyid[s->terrain_geom] != 0) {
        return fail(s, error, error_size, "model has no heightfield geom in the world body");
    }
    s->geom_role = malloc(sizeof(int) * (size_t)s->m->ngeom);
    for (int g = 0; g < s->m->ngeom; g++) {
        s->geom_role[g] = -1;
    }
    for (int leg = 0; leg < ROQ_LEGS; leg++) {
        for (int k = 0; k < 4; k++) {
            int jnt = JOINT_QPOS_FIRST + 4 * leg + k;
            if (s->m->jnt_type[jnt] != mjJNT_HINGE) {
                snprintf(msg, sizeof msg, "model joint %d (%s) is not a hinge", jnt, mj_id2name(s->m, mjOBJ_JOINT, jnt));
                return fail(s, error, error_size, msg);
            }
            if (k < 3) {
                s->qadr[3 * leg + k] = s->m->jnt_qposadr[jnt];
                s->dadr[3 * leg + k] = s->m->jnt_dofadr[jnt];
            } else {
                s->wheel_dadr[leg] = s->m->jnt_dofadr[jnt];
                int wheel_body = s->m->jnt_bodyid[jnt];
                if (s->m->body_geomnum[wheel_body] != 1) {
                    snprintf(msg, sizeof msg, "wheel body of leg %d has %d geoms, expected its foot only", leg,
                             s->m->body_geomnum[wheel_body]);
                    return fail(s, error, error_size, msg);
                }
                s->geom_role[s->m->body_geomadr[wheel_body]] = leg;
            }
        }
    }
    if (nfragile > ROQ_MAX_FRAGILE) {
        return fail(s, error, error_size, "too many fragile cells");
    }
    s->nfragile = nfragile;
    for (int i = 0; i < nfragile; i++) {
        char name[32];
        snprintf(name, sizeof name, "fragile_%d", i);
        int g = mj_name2id(s->m, mjOBJ_GEOM, name);
        if (g < 0) {
            snprintf(msg, sizeof msg, "model lacks geom %s", name);
            return fail(s, error, error_size, msg);
        }
        s->fragile_geom[i] = g;
        s->fragile_height[i] = fragile[6 * i + 4];
        s->fragile_strength[i] = fragile[6 * i + 5];
        s->geom_role[g] = 100 + i;
    }
    s->gyro_adr = -1;
    s->accel_adr = -1;
    for (int k = 0; k < s->m->nsensor; k++) {
        if (s->m->sensor_type[k] == mjSENS_GYRO) {
            s->gyro_adr = s->m->sensor_adr[k];
        } else if (s->m->sensor_type[k] == mjSENS_ACCELEROMETER) {
            s->accel_adr = s->m->sensor_adr[k];
        }
    }
    if (s->gyro_adr < 0 || s->accel_adr < 0) {
        return fail(s, error, error_size, "model lacks the IMU: a gyro and an accelerometer sensor on the body");
    }
    s->d = mj_makeData(s->m);
    for (int j = 0; j < ROQ_JOINTS; j++) {
        s->target[j] = params[P_INITIAL_POSE_0 + j % JOINTS_PER_LEG];
        s->d->qpos[s->qadr[j]] = s->target[j];
    }
    uint64_t seed = (uint64_t)(int64_t)params[P_NOISE_SEED];
    s->noise_state = seed * 0x9E3779B97F4A7C15ULL + 0x2545F4914F6CDD1DULL;
    if (s->noise_state == 0) {
        s->noise_state = 1;
    }
    s->imu_noise_state = (seed + 1) * 0xD1B54A32D192ED03ULL + 0x8BB84B93962EACC9ULL;
    if (s->imu_noise_state == 0) {
        s->imu_noise_state = 1;
    }
    if (params[P_NOISE] != 0) { /* a bias per axis, fixed for the run: gyro up to ±0.01 rad/s, accelerometer ±0.1 m/s^2 */
        for (int r = 0; r < 6; r++) {
            s->imu_bias[r] = (r < 3 ? 0.01 : 0.1) * noise_from(&s->imu_noise_state);
        }
    }
    memset(block, 0, ROQ_BLOCK_SIZE);
    *BLK_I(block, L_LAYOUT_VERSION) = ROQ_LAYOUT_VERSION;
    mj_forward(s->m, s->d);
    for (int r = 0; r < 3; r++) {
        BLK_D(s->stage, S_ACCEL)[r] = s->d->sensordata[s->accel_adr + r] + s->imu_bias[3 + r];
    }
    int64_t period = (int64_t)params[P_DEPTH_ROW_PERIOD];
    if (period < 1 || ROQ_DEPTH_W % period != 0) {
        snprintf(msg, sizeof msg, "depth row period %lld must divide the image width %d", (long long)period, ROQ_DEPTH_W);
        return fail(s, error, error_size, msg);
    }
    for (int64_t t = 0; t < period * ROQ_DEPTH_H; t++) { /* a whole first image, so readers never see an empty one */
        s->tick = t;
        state_sensors(s);
    }
    s->tick = 0;
    s->depth_frames = 1;
    if (params[P_RANGE_SENSORS] == 0) {
        BLK_D(s->stage, S_IR_RANGE)[0] = NAN;
        BLK_D(s->stage, S_ULTRASONIC_RANGE)[0] = NAN;
        for (int i = 0; i < ROQ_DEPTH_W * ROQ_DEPTH_H; i++) {
            BLK_F(s->stage, S_DEPTH)[i] = NAN;
        }
        s->depth_frames = 0;
    }
    *BLK_L(s->stage, S_DEPTH_FRAMES) = s->depth_frames;
    publish(s);
    return s;
}

void roq_close(roq_sim *s) {
    if (s == NULL) {
        return;
    }
    if (s->d) {
        mj_deleteData(s->d);
    }
    if (s->m) {
        mj_deleteModel(s->m);
    }
    free(s->geom_role);
    free(s->stage);
    free(s);
}

uint64_t roq_state_hash(const roq_sim *s) {
    uint64_t h = 1469598103934665603ULL;
#define HASH_BYTES(ptr, n)                                   \
    do {                                                     \
        const unsigned char *b_ = (const unsigned char *)(ptr); \
        for (size_t i_ = 0; i_ < (size_t)(n); i_++) {          \
            h ^= b_[i_];                                     \
            h *= 1099511628211ULL;                           \
        }                                                    \
    } while (0)
    HASH_BYTES(&s->d->time, sizeof(mjtNum));
    HASH_BYTES(s->d->qpos, sizeof(mjtNum) * s->m->nq);
    HASH_BYTES(s->d->qvel, sizeof(mjtNum) * s->m->nv);
    HASH_BYTES(s->d->qacc, sizeof(mjtNum) * s->m->nv);
    HASH_BYTES(s->fragile_broken, s->nfragile);
#undef HASH_BYTES
    return h;
}

int64_t roq_bare_step_nanos(roq_sim *s, int ticks) {
    mjData *d = mj_makeData(s->m);
    mj_copyData(d, s->m, s->d);
    struct timespec a, b;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (int i = 0; i < ticks; i++) {
        mj_step(s->m, d);
    }
    clock_gettime(CLOCK_MONOTONIC, &b);
    mj_deleteData(d);
    return (int64_t)(b.tv_sec - a.tv_sec) * 1000000000LL + (b.tv_nsec - a.tv_nsec);
}
