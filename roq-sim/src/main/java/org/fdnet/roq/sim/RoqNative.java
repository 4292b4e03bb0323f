package org.fdnet.roq.sim;

import java.nio.ByteBuffer;

/**
 * The JNI entry points of {@code libroqsim.so} (src/main/c/roq_jni.c). Only {@link RoqNativeLibrary} and
 * {@link RoqSimulator} call them, and never from inside the loop: the loop and Java meet in the shared block only.
 */
final class RoqNative {
    private RoqNative() {
    }

    /** ABI handshake: the C side's layout version, {@code ROQ_VERSION}. */
    static native int abiVersion();

    /** ABI handshake: the C side's {@code ROQ_BLOCK_SIZE}. */
    static native int blockSize();

    /** ABI handshake: the names of the C side's {@code ROQ_LAYOUT} table (roq_layout.h), in table order. */
    static native String[] layoutNames();

    /** ABI handshake: the values of the {@code ROQ_LAYOUT} table, in the order of {@link #layoutNames()}. */
    static native long[] layoutValues();

    /**
     * Loads the model file, fills the heightfield with {@code heights} (already scaled to 0..1), sets the robot in its initial pose and publishes the first
     * snapshot into {@code block}. Returns a handle; throws {@link IllegalStateException} with MuJoCo's message.
     */
    static native long open(String mjcfPath, float[] heights, double[] fragile, double[] params, ByteBuffer block);

    /** Runs {@code ticks} ticks on the caller's thread (stepped mode). */
    static native void step(long handle, int ticks);

    /** Starts the real-time thread; returns warnings (what could not be obtained), empty when none. */
    static native String start(long handle, int priority);

    /** Puts the calling thread under SCHED_FIFO at {@code priority}; 0, or the errno (EPERM without the right). */
    static native int fifoThisThread(int priority);

    /** Stops the real-time thread and waits for it. */
    static native void stop(long handle);

    /** Frees everything; the handle is dead afterwards. */
    static native void close(long handle);

    /** FNV-1a hash over the bits of time, qpos, qvel, qacc and the fragile cells' state. */
    static native long stateHash(long handle);

    /**
     * Runs a bare {@code mj_step} loop for {@code ticks} on a copy of the model's data; returns nanoseconds. Throws
     * {@link IllegalStateException} when MuJoCo cannot allocate the copy.
     */
    static native long bareStepNanos(long handle, int ticks);

    /**
     * A figure of the loaded model for checks against {@link RoqGeometry}: {@code what} 0 body mass (name = body),
     * 1 joint lower limit, 2 joint upper limit (name = joint), 3 whole mass, 4/5/6 x/y/z of geom {@code name} in the
     * world after the current state's kinematics, 7 joint armature, 8 joint frictionloss, 9 joint damping,
     * 10 the ground's height under {@code name} = "x y" (a ray down at the terrain and fragile cells), 11 / 12 the
     * distance along the ray {@code name} = "x y z vx vy vz" (unit vector) to the ground by roq-sim's own ray /
     * by MuJoCo's {@code mj_ray} (−1: no hit).
     * Returns NaN when the name is unknown.
     */
    static native double modelValue(long handle, int what, String name);
}
