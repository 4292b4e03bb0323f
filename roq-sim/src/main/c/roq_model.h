/*
 * roq_model: what does not change while the robot runs (like MuJoCo's mjModel) — MuJoCo's model, the named
 * parameters, the ids and addresses found once at open, and the fragile cells' figures. Built once by
 * roq_model_open; the tick reads it through a const pointer.
 *
 * The ONE place the model changes after open is roq_model_apply_edits (roq_model.c): a fragile cell that broke
 * drops out of the way and loses its collisions. roq_tick calls it at one safe point, between two steps (after
 * the previous tick's mj_step2, before this tick's mj_step1); see docs/explanation/roq-sim.md, "The one place the model
 * changes".
 */
#ifndef ROQ_MODEL_H
#define ROQ_MODEL_H

#include <stdint.h>
#include <mujoco/mujoco.h>
#include "roq_layout.h"

#define ROQ_GEOM_ROLE_CELL 100 /* geom_role of fragile cell i is ROQ_GEOM_ROLE_CELL + i */

/* The servo: PD on the target through a DC motor's current and voltage limits. */
typedef struct {
    double kp, kd;                /* N·m/rad, N·m·s/rad */
    double torque_constant;       /* N·m/A at the motor */
    double resistance;            /* Ω */
    double supply_voltage;        /* V */
    double current_limit;         /* A */
    double gear;                  /* ratio */
    double efficiency;            /* of the gear, 0..1 */
} roq_servo_params;

typedef struct {
    double kv;                    /* N·m per rad/s of speed error */
    double max_torque;            /* N·m */
    double max_speed;             /* rad/s: commands beyond are clamped and counted */
} roq_wheel_params;

/* Per joint of a leg (yaw, lift, knee): the same on every leg. */
typedef struct {
    double min[ROQ_JOINTS_PER_LEG], max[ROQ_JOINTS_PER_LEG]; /* rad: commands beyond are clamped and counted */
    double initial[ROQ_JOINTS_PER_LEG];                      /* the pose the robot is set down in */
} roq_joint_params;

/* A range sensor on the body: where, which way, how far. */
typedef struct {
    double position[3];           /* body frame, m */
    double angle;                 /* rad: the IR's pitch down; the ultrasonic cone's half angle, swept in yaw */
    double max_range;             /* m */
} roq_ranger_params;

typedef struct {
    double position[3];           /* body frame, m */
    double pitch_down, fov_x, fov_y; /* rad */
    double max_range;             /* m */
} roq_camera_params;

typedef struct {
    roq_servo_params servo;
    roq_wheel_params wheel;
    roq_joint_params joint;
    int break_hold_ticks;         /* a fragile cell breaks after this many ticks over its strength */
    roq_ranger_params ir, ultrasonic;
    roq_camera_params camera;
    int noise;                    /* sensor noise on */
    int64_t noise_seed;
    int range_sensors;            /* rays on: IR, ultrasonic and the depth image */
    int64_t ir_period, ultrasonic_period, depth_row_period; /* ticks */
} roq_params;

/* A fragile cell's figures (its state is roq_cell_state). */
typedef struct {
    int geom;                     /* MuJoCo geom "fragile_<i>" */
    double height;                /* m its top stands above the terrain */
    double strength;              /* N of normal force it bears indefinitely */
} roq_fragile_cell;

typedef struct {
    mjModel *m;
    roq_params params;
    int body_id;                  /* the robot's free body */
    int terrain_geom;             /* the heightfield geom */
    int qadr[ROQ_JOINTS], dadr[ROQ_JOINTS];
    int wheel_dadr[ROQ_LEGS];
    int *geom_role;               /* per geom: -1, leg 0..3 for a foot, ROQ_GEOM_ROLE_CELL + i for fragile cell i */
    int gyro_adr, accel_adr;      /* MuJoCo's gyro and accelerometer sensors on the body's imu site */
    int nfragile;
    roq_fragile_cell fragile[ROQ_MAX_FRAGILE];
} roq_model;

struct roq_state;

/* Builds the model: the MJCF file, the heightfield's points (0..1 of the elevation range), the fragile cells'
   figures (F_STRIDE doubles each, see roq_layout.h) and the parameter array (P_COUNT doubles). NULL on failure,
   with what failed (the joint, the cell, the allocation) in error. */
roq_model *roq_model_open(const char *mjcf, const float *heights, int nheights, const double *fragile,
                          int nfragile, const double *params, char *error, int error_size);
void roq_model_close(roq_model *model);

/* The one place the model changes after open: applies the model edits the state has queued (cells that broke). */
void roq_model_apply_edits(roq_model *model, struct roq_state *state);

#endif
