/*
 * The model: built once at open (may allocate and report), then constant while running except for
 * roq_model_apply_edits, the one documented place it changes.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "roq_sim.h"

#define JOINT_QPOS_FIRST 1 /* joint 0 is the free joint; then per leg yaw, lift, knee, wheel */

static void ranger(const double *p, int at, roq_ranger_params *out) {
    memcpy(out->position, p + at, sizeof out->position);
    out->angle = p[at + 3];
    out->max_range = p[at + 4];
}

/* The parameter array (indices P_* of roq_layout.h, filled by Java's NativeParameters) as named structs. */
static void unpack_params(const double *p, roq_params *out) {
    out->servo.kp = p[P_KP];
    out->servo.kd = p[P_KD];
    out->servo.torque_constant = p[P_TORQUE_CONSTANT];
    out->servo.resistance = p[P_RESISTANCE];
    out->servo.supply_voltage = p[P_SUPPLY_VOLTAGE];
    out->servo.current_limit = p[P_CURRENT_LIMIT];
    out->servo.gear = p[P_GEAR];
    out->servo.efficiency = p[P_EFFICIENCY];
    out->wheel.kv = p[P_WHEEL_KV];
    out->wheel.max_torque = p[P_WHEEL_TORQUE];
    out->wheel.max_speed = p[P_WHEEL_SPEED];
    for (int k = 0; k < ROQ_JOINTS_PER_LEG; k++) {
        out->joint.min[k] = p[P_JOINT_MIN_0 + k];
        out->joint.max[k] = p[P_JOINT_MAX_0 + k];
        out->joint.initial[k] = p[P_INITIAL_POSE_0 + k];
    }
    out->break_hold_ticks = (int)p[P_BREAK_HOLD_TICKS];
    ranger(p, P_IR_0, &out->ir);
    ranger(p, P_US_0, &out->ultrasonic);
    memcpy(out->camera.position, p + P_CAMERA_0, sizeof out->camera.position);
    out->camera.pitch_down = p[P_CAMERA_0 + 3];
    out->camera.fov_x = p[P_CAMERA_0 + 4];
    out->camera.fov_y = p[P_CAMERA_0 + 5];
    out->camera.max_range = p[P_CAMERA_0 + 6];
    out->noise = p[P_NOISE] != 0;
    out->noise_seed = (int64_t)p[P_NOISE_SEED];
    out->range_sensors = p[P_RANGE_SENSORS] != 0;
    out->ir_period = (int64_t)p[P_IR_PERIOD];
    out->ultrasonic_period = (int64_t)p[P_US_PERIOD];
    out->depth_row_period = (int64_t)p[P_DEPTH_ROW_PERIOD];
}

/* The periods the tick divides by; 0 when fine, else the message. */
static int check_periods(const roq_params *p, char *msg, int size) {
    if (p->ir_period < 1 || p->ultrasonic_period < 1) {
        snprintf(msg, size, "range sensor periods must be at least 1 tick: IR %lld, ultrasonic %lld",
                 (long long)p->ir_period, (long long)p->ultrasonic_period);
        return 1;
    }
    if (p->depth_row_period < 1 || ROQ_DEPTH_WIDTH % p->depth_row_period != 0) {
        snprintf(msg, size, "depth row period %lld must divide the image width %d", (long long)p->depth_row_period,
                 ROQ_DEPTH_WIDTH);
        return 1;
    }
    return 0;
}

static roq_model *fail(roq_model *model, char *error, int size, const char *message) {
    snprintf(error, size, "%s", message);
    roq_model_close(model);
    return NULL;
}

/* The leg joints: 4 hinges per leg (yaw, lift, knee, wheel), the wheel body carrying the foot's geom only. */
static int find_legs(roq_model *model, char *msg, int size) {
    const mjModel *m = model->m;
    for (int leg = 0; leg < ROQ_LEGS; leg++) {
        for (int k = 0; k < 4; k++) {
            int jnt = JOINT_QPOS_FIRST + 4 * leg + k;
            if (m->jnt_type[jnt] != mjJNT_HINGE) {
                snprintf(msg, size, "model joint %d (%s) is not a hinge", jnt, mj_id2name(m, mjOBJ_JOINT, jnt));
                return 1;
            }
            if (k < 3) {
                model->qadr[3 * leg + k] = m->jnt_qposadr[jnt];
                model->dadr[3 * leg + k] = m->jnt_dofadr[jnt];
            } else {
                model->wheel_dadr[leg] = m->jnt_dofadr[jnt];
                int wheel_body = m->jnt_bodyid[jnt];
                if (m->body_geomnum[wheel_body] != 1) {
                    snprintf(msg, size, "wheel body of leg %d (joint %s) has %d geoms, expected its foot only", leg,
                             mj_id2name(m, mjOBJ_JOINT, jnt), m->body_geomnum[wheel_body]);
                    return 1;
                }
                model->geom_role[m->body_geomadr[wheel_body]] = leg;
            }
        }
    }
    return 0;
}

/* The fragile cells: geom "fragile_<i>" for each, its figures from F_STRIDE doubles. */
static int find_cells(roq_model *model, const double *fragile, int nfragile, char *msg, int size) {
    if (nfragile > ROQ_MAX_FRAGILE) {
        snprintf(msg, size, "%d fragile cells, at most %d", nfragile, ROQ_MAX_FRAGILE);
        return 1;
    }
    model->nfragile = nfragile;
    for (int i = 0; i < nfragile; i++) {
        char name[32];
        snprintf(name, sizeof name, "fragile_%d", i);
        int g = mj_name2id(model->m, mjOBJ_GEOM, name);
        if (g < 0) {
            snprintf(msg, size, "model lacks geom %s (fragile cell %d)", name, i);
            return 1;
        }
        roq_fragile_cell *cell = &model->fragile[i];
        cell->geom = g;
        cell->height = fragile[F_STRIDE * i + F_HEIGHT];
        cell->strength = fragile[F_STRIDE * i + F_STRENGTH];
        model->geom_role[g] = ROQ_GEOM_ROLE_CELL + i;
    }
    return 0;
}

roq_model *roq_model_open(const char *mjcf, const float *heights, int nheights, const double *fragile,
                          int nfragile, const double *params, char *error, int error_size) {
    char msg[1200];
    roq_model *model = calloc(1, sizeof(roq_model));
    if (model == NULL) {
        snprintf(error, error_size, "out of memory for roq_model (%zu bytes)", sizeof(roq_model));
        return NULL;
    }
    unpack_params(params, &model->params);
    if (check_periods(&model->params, msg, sizeof msg)) {
        return fail(model, error, error_size, msg);
    }
    char load_error[1000] = "";
    model->m = mj_loadXML(mjcf, NULL, load_error, sizeof load_error);
    if (model->m == NULL) {
        snprintf(msg, sizeof msg, "MuJoCo refused the model %s: %s", mjcf, load_error);
        return fail(model, error, error_size, msg);
    }
    mjModel *m = model->m;
    if (m->nhfield != 1 || m->hfield_nrow[0] * m->hfield_ncol[0] != nheights) {
        snprintf(msg, sizeof msg, "model has %d heightfields of %d points, the course %d points",
                 m->nhfield, m->nhfield ? m->hfield_nrow[0] * m->hfield_ncol[0] : 0, nheights);
        return fail(model, error, error_size, msg);
    }
    for (int i = 0; i < nheights; i++) { /* Java scaled them to 0..1 of the elevation range */
        m->hfield_data[i] = heights[i];
    }
    if (m->njnt != 1 + ROQ_LEGS * 4 || m->jnt_type[0] != mjJNT_FREE) {
        snprintf(msg, sizeof msg, "model has %d joints, expected a free joint and %d leg joints", m->njnt,
                 ROQ_LEGS * 4);
        return fail(model, error, error_size, msg);
    }
    model->body_id = m->jnt_bodyid[0];
    model->terrain_geom = -1;
    for (int g = 0; g < m->ngeom; g++) {
        if (m->geom_type[g] == mjGEOM_HFIELD) {
            model->terrain_geom = g;
        }
    }
    if (model->terrain_geom < 0 || m->geom_bodyid[model->terrain_geom] != 0) {
        return fail(model, error, error_size, "model has no heightfield geom in the world body");
    }
    model->geom_role = malloc(sizeof(int) * (size_t)m->ngeom);
    if (model->geom_role == NULL) {
        snprintf(msg, sizeof msg, "out of memory for the geom roles (%d geoms)", m->ngeom);
        return fail(model, error, error_size, msg);
    }
    for (int g = 0; g < m->ngeom; g++) {
        model->geom_role[g] = -1;
    }
    if (find_legs(model, msg, sizeof msg) || find_cells(model, fragile, nfragile, msg, sizeof msg)) {
        return fail(model, error, error_size, msg);
    }
    model->gyro_adr = -1;
    model->accel_adr = -1;
    for (int k = 0; k < m->nsensor; k++) {
        if (m->sensor_type[k] == mjSENS_GYRO) {
            model->gyro_adr = m->sensor_adr[k];
        } else if (m->sensor_type[k] == mjSENS_ACCELEROMETER) {
            model->accel_adr = m->sensor_adr[k];
        }
    }
    if (model->gyro_adr < 0 || model->accel_adr < 0) {
        return fail(model, error, error_size, "model lacks the IMU: a gyro and an accelerometer sensor on the body");
    }
    return model;
}

void roq_model_close(roq_model *model) {
    if (model == NULL) {
        return;
    }
    if (model->m) {
        mj_deleteModel(model->m);
    }
    free(model->geom_role);
    free(model);
}

/*
 * THE one place the model changes after open. A cell that broke (under load, or by a break stimulus) drops
 * 2 cm below the terrain it stood on and stops colliding. Called by roq_tick only, at its safe point: after
 * the previous tick's mj_step2 and before this tick's mj_step1, so no MuJoCo step is ever in progress, and
 * mj_step1 (kinematics, collision) is the first thing to read the changed geom. Nothing between the break and
 * this point reads a fragile geom's pose or collision bits from the model: the rays take its pose from mjData
 * (geom_xpos, computed by mj_step1) and skip broken cells by the state.
 */
void roq_model_apply_edits(roq_model *model, roq_state *state) {
    mjModel *m = model->m;
    for (int k = 0; k < state->npending_breaks; k++) {
        const roq_fragile_cell *cell = &model->fragile[state->pending_break[k]];
        m->geom_contype[cell->geom] = 0;
        m->geom_conaffinity[cell->geom] = 0;
        m->geom_pos[3 * cell->geom + 2] -= cell->height + 0.02;
    }
    state->npending_breaks = 0;
}
