/*
 * JNI glue: org.fdnet.roq.sim.RoqNative. Called to open, step, start, stop and close; never per tick. A handle is
 * one roq_handle: the model, the state and the real-time thread, each its own struct.
 */
#include <jni.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "org_fdnet_roq_sim_RoqNative.h"
#include "roq_loop.h"
#include "roq_sim.h"

typedef struct {
    roq_model *model;
    roq_state *state;
    roq_rt rt;
} roq_handle;

static void throw_state(JNIEnv *env, const char *message) {
    jclass c = (*env)->FindClass(env, "java/lang/IllegalStateException");
    if (c != NULL) {
        (*env)->ThrowNew(env, c, message);
    }
}

static roq_handle *handle_of(jlong handle) {
    return (roq_handle *)(intptr_t)handle;
}

JNIEXPORT jint JNICALL Java_org_fdnet_roq_sim_RoqNative_abiVersion(JNIEnv *env, jclass cls) {
    (void)env; (void)cls;
    return ROQ_VERSION;
}

JNIEXPORT jint JNICALL Java_org_fdnet_roq_sim_RoqNative_blockSize(JNIEnv *env, jclass cls) {
    (void)env; (void)cls;
    return ROQ_BLOCK_SIZE;
}

/* The table of roq_layout.h, expanded from the same ROQ_LAYOUT list as the enum the C code uses. */
#define ROQ_LAYOUT_NAME(name, value) #name,
#define ROQ_LAYOUT_VALUE(name, value) (value),
static const char *const layout_names[] = {ROQ_LAYOUT(ROQ_LAYOUT_NAME)};
static const jlong layout_values[] = {ROQ_LAYOUT(ROQ_LAYOUT_VALUE)};
#undef ROQ_LAYOUT_NAME
#undef ROQ_LAYOUT_VALUE
#define LAYOUT_ENTRIES ((jsize)(sizeof layout_values / sizeof layout_values[0]))

JNIEXPORT jobjectArray JNICALL Java_org_fdnet_roq_sim_RoqNative_layoutNames(JNIEnv *env, jclass cls) {
    (void)cls;
    jclass string = (*env)->FindClass(env, "java/lang/String");
    if (string == NULL) {
        return NULL;
    }
    jobjectArray a = (*env)->NewObjectArray(env, LAYOUT_ENTRIES, string, NULL);
    for (jsize i = 0; a != NULL && i < LAYOUT_ENTRIES; i++) {
        jstring name = (*env)->NewStringUTF(env, layout_names[i]);
        if (name == NULL) {
            return NULL; /* OutOfMemoryError pending */
        }
        (*env)->SetObjectArrayElement(env, a, i, name);
        (*env)->DeleteLocalRef(env, name);
    }
    return a;
}

JNIEXPORT jlongArray JNICALL Java_org_fdnet_roq_sim_RoqNative_layoutValues(JNIEnv *env, jclass cls) {
    (void)cls;
    jlongArray a = (*env)->NewLongArray(env, LAYOUT_ENTRIES);
    if (a != NULL) {
        (*env)->SetLongArrayRegion(env, a, 0, LAYOUT_ENTRIES, layout_values);
    }
    return a;
}

/* Opens the model and the state; NULL with the message in error. */
static roq_handle *open_handle(const char *file, const jfloat *h, jsize nheights, const jdouble *f, jsize nfragile,
                               const jdouble *p, unsigned char *mem, char *error, int error_size) {
    roq_handle *handle = calloc(1, sizeof(roq_handle));
    if (handle == NULL) {
        snprintf(error, error_size, "roq-sim: out of memory for the simulator handle (%zu bytes)", sizeof(roq_handle));
        return NULL;
    }
    handle->rt.dma_fd = -1;
    handle->model = roq_model_open(file, h, nheights, f, nfragile, p, error, error_size);
    if (handle->model != NULL) {
        handle->state = roq_state_open(handle->model, mem, error, error_size);
    }
    if (handle->state == NULL) {
        roq_model_close(handle->model);
        free(handle);
        return NULL;
    }
    return handle;
}

JNIEXPORT jlong JNICALL Java_org_fdnet_roq_sim_RoqNative_open(JNIEnv *env, jclass cls, jstring path,
        jfloatArray heights, jdoubleArray fragile, jdoubleArray params, jobject block) {
    (void)cls;
    char error[1300] = "";
    unsigned char *mem = (*env)->GetDirectBufferAddress(env, block);
    if (mem == NULL || (*env)->GetDirectBufferCapacity(env, block) < ROQ_BLOCK_SIZE) {
        throw_state(env, "roq-sim: the shared block is not a direct buffer of ROQ_BLOCK_SIZE bytes");
        return 0;
    }
    if ((*env)->GetArrayLength(env, params) != P_COUNT) {
        snprintf(error, sizeof error, "roq-sim: parameter array of %d values, P_COUNT is %d (Java and C out of step)",
                 (int)(*env)->GetArrayLength(env, params), P_COUNT);
        throw_state(env, error);
        return 0;
    }
    jsize nfigures = (*env)->GetArrayLength(env, fragile);
    if (nfigures % F_STRIDE != 0) {
        snprintf(error, sizeof error, "roq-sim: fragile cell figures: %d values, not a multiple of F_STRIDE %d",
                 (int)nfigures, F_STRIDE);
        throw_state(env, error);
        return 0;
    }
    const char *file = (*env)->GetStringUTFChars(env, path, NULL);
    jsize nheights = (*env)->GetArrayLength(env, heights);
    jfloat *h = file ? (*env)->GetFloatArrayElements(env, heights, NULL) : NULL;
    jdouble *f = h ? (*env)->GetDoubleArrayElements(env, fragile, NULL) : NULL;
    jdouble *p = f ? (*env)->GetDoubleArrayElements(env, params, NULL) : NULL;
    roq_handle *handle = NULL;
    if (p == NULL) {
        (*env)->ExceptionClear(env); /* the JVM's bare OutOfMemoryError: replaced by one naming what failed */
        snprintf(error, sizeof error, "roq-sim: out of memory for the %s handed to open",
                 file == NULL ? "model path" : h == NULL ? "heights" : f == NULL ? "fragile cells" : "parameters");
    } else {
        handle = open_handle(file, h, nheights, f, nfigures / F_STRIDE, p, mem, error, sizeof error);
    }
    if (p) (*env)->ReleaseDoubleArrayElements(env, params, p, JNI_ABORT);
    if (f) (*env)->ReleaseDoubleArrayElements(env, fragile, f, JNI_ABORT);
    if (h) (*env)->ReleaseFloatArrayElements(env, heights, h, JNI_ABORT);
    if (file) (*env)->ReleaseStringUTFChars(env, path, file);
    if (handle == NULL) {
        throw_state(env, error);
        return 0;
    }
    return (jlong)(intptr_t)handle;
}

JNIEXPORT void JNICALL Java_org_fdnet_roq_sim_RoqNative_step(JNIEnv *env, jclass cls, jlong handle, jint ticks) {
    (void)env; (void)cls;
    roq_handle *h = handle_of(handle);
    for (jint i = 0; i < ticks; i++) {
        roq_tick(h->model, h->state);
    }
}

JNIEXPORT jstring JNICALL Java_org_fdnet_roq_sim_RoqNative_start(JNIEnv *env, jclass cls, jlong handle,
        jint priority) {
    (void)cls;
    char warnings[512];
    roq_handle *h = handle_of(handle);
    int rc = roq_rt_start(&h->rt, h->model, h->state, priority, warnings, sizeof warnings);
    if (rc != 0) {
        char msg[600];
        snprintf(msg, sizeof msg, "roq-sim: cannot start the joint loop thread (%s)", strerror(rc));
        throw_state(env, msg);
        return NULL;
    }
    return (*env)->NewStringUTF(env, warnings);
}

JNIEXPORT jint JNICALL Java_org_fdnet_roq_sim_RoqNative_fifoThisThread(JNIEnv *env, jclass cls, jint priority) {
    (void)env; (void)cls;
    return roq_thread_fifo(priority);
}

JNIEXPORT void JNICALL Java_org_fdnet_roq_sim_RoqNative_stop(JNIEnv *env, jclass cls, jlong handle) {
    (void)env; (void)cls;
    roq_rt_stop(&handle_of(handle)->rt);
}

JNIEXPORT void JNICALL Java_org_fdnet_roq_sim_RoqNative_close(JNIEnv *env, jclass cls, jlong handle) {
    (void)env; (void)cls;
    roq_handle *h = handle_of(handle);
    roq_rt_stop(&h->rt);
    roq_state_close(h->state);
    roq_model_close(h->model);
    free(h);
}

JNIEXPORT jlong JNICALL Java_org_fdnet_roq_sim_RoqNative_stateHash(JNIEnv *env, jclass cls, jlong handle) {
    (void)env; (void)cls;
    roq_handle *h = handle_of(handle);
    return (jlong)roq_state_hash(h->model, h->state);
}

JNIEXPORT jlong JNICALL Java_org_fdnet_roq_sim_RoqNative_bareStepNanos(JNIEnv *env, jclass cls, jlong handle,
        jint ticks) {
    (void)cls;
    roq_handle *h = handle_of(handle);
    int64_t nanos = roq_bare_step_nanos(h->model, h->state, ticks);
    if (nanos < 0) {
        throw_state(env, "roq-sim: MuJoCo could not allocate the mjData copy for the bare-step measurement");
    }
    return nanos;
}

JNIEXPORT jdouble JNICALL Java_org_fdnet_roq_sim_RoqNative_modelValue(JNIEnv *env, jclass cls, jlong handle,
        jint what, jstring jname) {
    (void)cls;
    const roq_handle *h = handle_of(handle);
    const mjModel *m = h->model->m;
    const mjData *d = h->state->d;
    const char *name = (*env)->GetStringUTFChars(env, jname, NULL);
    if (name == NULL) {
        return NAN; /* OutOfMemoryError pending */
    }
    double v = NAN;
    int id;
    switch (what) {
    case 0:
        id = mj_name2id(m, mjOBJ_BODY, name);
        if (id >= 0) v = m->body_mass[id];
        break;
    case 1: case 2: case 7: case 8: case 9:
        id = mj_name2id(m, mjOBJ_JOINT, name);
        if (id >= 0) {
            int dof = m->jnt_dofadr[id];
            v = what == 1 ? m->jnt_range[2 * id] : what == 2 ? m->jnt_range[2 * id + 1]
              : what == 7 ? m->dof_armature[dof] : what == 8 ? m->dof_frictionloss[dof] : m->dof_damping[dof];
        }
        break;
    case 3:
        v = mj_getTotalmass(m);
        break;
    case 4: case 5: case 6:
        id = mj_name2id(m, mjOBJ_GEOM, name);
        if (id >= 0) v = d->geom_xpos[3 * id + (what - 4)];
        break;
    case 10: { /* ground height under "x y": a ray straight down at the ground geoms */
        double x, y;
        if (sscanf(name, "%lf %lf", &x, &y) == 2) {
            static const mjtByte ground_only[mjNGROUP] = {1, 0, 0, 0, 0, 0};
            mjtNum pnt[3] = {x, y, 10.0}, vec[3] = {0, 0, -1};
            int geom = -1;
            mjtNum dist = mj_ray(m, d, pnt, vec, ground_only, 1, -1, &geom);
            if (dist >= 0) v = 10.0 - dist;
        }
        break;
    }
    case 11: case 12: { /* a ray "x y z vx vy vz" (unit vector) at the ground: 11 roq-sim's, 12 MuJoCo's mj_ray */
        double r[6];
        if (sscanf(name, "%lf %lf %lf %lf %lf %lf", r, r + 1, r + 2, r + 3, r + 4, r + 5) == 6) {
            static const mjtByte ground_only[mjNGROUP] = {1, 0, 0, 0, 0, 0};
            int geom = -1;
            v = what == 11 ? roq_ground_ray(h->model, h->state, r, r + 3, 1e6)
                            : mj_ray(m, d, r, r + 3, ground_only, 1, -1, &geom);
        }
        break;
    }
    default:
        break;
    }
    (*env)->ReleaseStringUTFChars(env, jname, name);
    return v;
}
