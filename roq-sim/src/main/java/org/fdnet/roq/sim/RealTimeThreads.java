package org.fdnet.roq.sim;

import java.util.concurrent.atomic.AtomicBoolean;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Puts the Java threads on the path from a snapshot to a command — the real-time bridge's thread and the network's
 * workers ({@link org.fdnet.runtime.engine.RuntimeOptions#workerStart}) — under SCHED_FIFO, one step below the joint
 * loop's priority, so the loop still wins its core and every ordinary process loses to them.
 *
 * <p>Why: on a machine loaded by other work (load 7-8 on 2 cores) the tilt reflex's answer waited 0.5-2.5 ms for the
 * bridge thread to get a core back and 7-22 ms for a worker that had been preempted in the middle of the reflex's
 * firing (bench roq (b) {@code --trace}). The threads sleep between snapshots, so they take little: the network's
 * firings on each snapshot, a fraction of a millisecond. Hazard: a Relation that computes for long holds a core at
 * this priority (the kernel's real-time throttling still leaves ordinary threads 5 %).
 */
public final class RealTimeThreads {
    private static final Logger LOG = LoggerFactory.getLogger(RealTimeThreads.class);
    /** One below the joint loop's SCHED_FIFO priority ({@link SimOptions#DEFAULT_PRIORITY}). */
    public static final int NETWORK_PRIORITY = SimOptions.DEFAULT_PRIORITY - 1;
    private static final int EPERM = 1;
    private static final AtomicBoolean WARNED = new AtomicBoolean();

    private RealTimeThreads() {
    }

    /**
     * Puts the calling thread under SCHED_FIFO at {@link #NETWORK_PRIORITY}. Returns false, and warns once per
     * process, when the system refuses (not root, no CAP_SYS_NICE): the thread then runs on as it was.
     */
    public static boolean promoteCurrentThread() {
        RoqNativeLibrary.ensureLoaded();
        int errno = RoqNative.fifoThisThread(NETWORK_PRIORITY);
        if (errno != 0 && WARNED.compareAndSet(false, true)) {
            LOG.warn("roq-sim: thread {} (and any other on the network's path) runs without SCHED_FIFO {}: errno {}{}",
                    Thread.currentThread().getName(), NETWORK_PRIORITY, errno,
                    errno == EPERM ? " (not permitted: run as root or grant CAP_SYS_NICE for real-time figures)" : "");
        }
        return errno == 0;
    }
}
