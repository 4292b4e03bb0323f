/* JNI glue: org.fdnet.roq.sim.RoqNative. Called to open, step, start, stop and close; never per tick. */
#include <jni.h>
#include <stdio.h>
#include <string.h>
#include "org_fdnet_roq_sim_RoqNative.h"
#include "roq_sim.h"

static void throw_state(JNIEnv *env, const char *message) {
    jclass c = (*env)->FindClass(env, "java/lang/IllegalStateException");
    if (c != NULL) {
        (*env)->ThrowNew(env, c, message);
    }
}

static roq_sim *sim(jlong handle) {
    return (roq_sim *)(intptr_t)handle;
}

JNIEXPORT jint JNICALL Java_org_fdnet_roq_sim_RoqNative_abiVersion(JNIEnv *env, jclass cls) {
    (void)env; (void)cls;
    return ROQ_LAYOUT_VERSION;
}

JNIEXPORT jint JNICALL Java_org_fdnet_roq_sim_RoqNative_blockSize(JNIEnv *env, jclass cls) {
    (void)env; (void)cls;
    return ROQ_BLOCK_SIZE;
}

JNIEXPORT jintArray JNICALL Java_org_fdnet_roq_sim_RoqNative_layoutOffsets(JNIEnv *env, jclass cls) {
    (void)cls;
    static const jint offsets[] = ROQ_LAYOUT_OFFSETS;
    jsize n = (jsize)(sizeof offsets / sizeof offsets[0]);
    jintArray a = (*env)->NewIntArray(env, n);
    if (a != NULL) {
        (*env)->SetIntArrayRegion(env, a, 0, n, offsets);
    }
    return a;
}

JNIEXPORT jlong JNICALL Java_org_fdnet_roq_sim_RoqNative_open(JNIEnv *env, jclass cls, jstring path,
        jfloatArray heights, jdoubleArray fragile, jdoubleArray params, jobject block) {
    (void)cls;
    unsigned char *mem = (*env)->GetDirectBufferAddress(env, block);
    if (mem == NULL || (*env)->GetDirectBufferCapacity(env, block) < ROQ_BLOCK_SIZE) {
        throw_state(env, "roq-sim: the shared block is not a direct buffer of ROQ_BLOCK_SIZE bytes");
        return 0;
    }
    if ((*env)->GetArrayLength(env, params) != P_COUNT) {
        throw_state(env, "roq-sim: parameter array length differs from P_COUNT (Java and C out of step)");
        return 0;
    }
    const char *file = (*env)->GetStringUTFChars(env, path, NULL);
    jsize nheights = (*env)->GetArrayLength(env, heights);
    jsize nfragile = (*env)->GetArrayLength(env, fragile) / 6;
    jfloat *h = (*env)->GetFloatArrayElements(env, heights, NULL);
    jdouble *f = (*env)->GetDoubleArrayElements(env, fragile, NULL);
    jdouble *p = (*env)->GetDoubleArrayElements(env, params, NULL);
    char error[1300] = "";
    roq_sim *s = roq_open(file, h, nheights, f, nfragile, p, mem, error, sizeof error);
    (*env)->ReleaseDoubleArrayElements(env, params, p, JNI_ABORT);
    (*env)->ReleaseDoubleArrayElements(env, fragile, f, JNI_ABORT);
    (*env)->ReleaseFloatArrayElements(env, heights, h, JNI_ABORT);
    (*env)->ReleaseStringUTFChars(env, path, file);
    if (s == NULL) {
        throw_state(env, error);
        return 0;
    }
    return (jlong)(intptr_t)s;
}

JNIEXPORT void JNICALL Java_org_fdnet_roq_sim_RoqNative_step(JNIEnv *env, jclass cls, jlong handle, jint ticks) {
    (void)env; (void)cls;
    roq_sim *s = sim(handle);
    for (jint i = 0; i < ticks; i++) {
        roq_tick(s);
    }
}

JNIEXPORT jstring JNICALL Java_org_fdnet_roq_sim_RoqNative_start(JNIEnv *env, jclass cls, jlong handle,
        jint priority) {
    (void)cls;
    char warnings[512];
    int rc = roq_start(sim(handle), priority, warnings, sizeof warnings);
    if (rc != 0) {
        char msg[600];
        snprintf(msg, sizeof msg, "roq-sim: cannot start the joint loop thread (%s)", strerror(rc));
        throw_state(env, msg);
        return NULL;
    }
    return (*env)->NewStringUTF(env, warnings);
}

JNIEXPORT void JNICALL Java_org_fdnet_roq_sim_RoqNative_stop(JNIEnv *env, jclass cls, jlong handle) {
    (void)env; (void)cls;
    roq_stop(sim(handle));
}

JNIEXPORT void JNICALL Java_org_fdnet_roq_sim_RoqNative_close(JNIEnv *env, jclass cls, jlong handle) {
    (void)env; (void)cls;
    roq_sim *s = sim(handle);
    roq_stop(s);
    roq_close(s);
}

JNIEXPORT jlong JNICALL Java_org_fdnet_roq_sim_RoqNative_stateHash(JNIEnv *env, jclass cls, jlong handle) {
    (void)env; (void)cls;
    return (jlong)roq_state_hash(sim(handle));
}

JNIEXPORT jlong JNICALL Java_org_fdnet_roq_sim_RoqNative_bareStepNanos(JNIEnv *env, jclass cls, jlong handle,
        jint ticks) {
    (void)env; (void)cls;
    return roq_bare_step_nanos(sim(handle), ticks);
}

JNIEXPORT jdouble JNICALL Java_org_fdnet_roq_sim_RoqNative_modelValue(JNIEnv *env, jclass cls, jlong handle,
        jint what, jstring jname) {
    (void)cls;
    roq_sim *s = sim(handle);
    const mjModel *m = s->m;
    const char *name = (*env)->GetStringUTFChars(env, jname, NULL);
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
        if (id >= 0) v = s->d->geom_xpos[3 * id + (what - 4)];
        break;
    case 10: { /* ground height under "x y": a ray straight down at the ground geoms */
        double x, y;
        if (sscanf(name, "%lf %lf", &x, &y) == 2) {
            static const mjtByte ground_only[mjNGROUP] = {1, 0, 0, 0, 0, 0};
            mjtNum pnt[3] = {x, y, 10.0}, vec[3] = {0, 0, -1};
            int geom = -1;
            mjtNum dist = mj_ray(m, s->d, pnt, vec, ground_only, 1, -1, &geom);
            if (dist >= 0) v = 10.0 - dist;
        }
        break;
    }
    case 11: case 12: { /* a ray "x y z vx vy vz" (unit vector) at the ground: 11 roq-sim's, 12 MuJoCo's mj_ray */
        double r[6];
        if (sscanf(name, "%lf %lf %lf %lf %lf %lf", r, r + 1, r + 2, r + 3, r + 4, r + 5) == 6) {
            static const mjtByte ground_only[mjNGROUP] = {1, 0, 0, 0, 0, 0};
            int geom = -1;
            v = what == 11 ? roq_ground_ray(s, r, r + 3, 1e6) : mj_ray(m, s->d, r, r + 3, ground_only, 1, -1, &geom);
        }
        break;
    }
    default:
        break;
    }
    (*env)->ReleaseStringUTFChars(env, jname, name);
    return v;
}
