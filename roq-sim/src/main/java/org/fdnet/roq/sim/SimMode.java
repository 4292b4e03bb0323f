package org.fdnet.roq.sim;

/** How the joint loop advances time. */
public enum SimMode {
    /**
     * The C loop runs on its own thread at 1 kHz on absolute deadlines (SCHED_FIFO when permitted); Java reads
     * snapshots and sends commands while it runs. {@link RoqSimulator#step(int)} is refused.
     */
    REAL_TIME,
    /**
     * No thread and no wall clock: {@link RoqSimulator#step(int)} runs the same tick code n times on the caller's
     * thread. Bit-for-bit reproducible; what tests and CI use.
     */
    STEPPED
}
