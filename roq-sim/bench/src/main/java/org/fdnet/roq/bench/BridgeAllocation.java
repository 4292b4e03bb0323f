package org.fdnet.roq.bench;

import java.lang.management.ManagementFactory;
import java.util.Locale;
import org.fdnet.roq.bridge.SimBridge;

/**
 * What the real-time bridge's thread allocates a snapshot (bench roq (b) {@code --trace}): reading and feeding the
 * sensors, and every Relation that fires inline on it, down to the command. Garbage made there is what the young
 * collections, the pauses on the path, are made of.
 */
final class BridgeAllocation {
    private static final String THREAD = "roq-bridge";

    private final SimBridge bridge;
    private final long thread;
    private final long bytes;
    private final long cycles;

    private BridgeAllocation(SimBridge bridge, long thread) {
        this.bridge = bridge;
        this.thread = thread;
        this.bytes = allocated(thread);
        this.cycles = bridge.cycles();
    }

    /** From now on; {@code null} when the JVM cannot count a thread's allocation or the thread is not found. */
    static BridgeAllocation start(SimBridge bridge) {
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.getName().equals(THREAD) && allocated(t.getId()) >= 0) {
                return new BridgeAllocation(bridge, t.getId());
            }
        }
        return null;
    }

    String describe() {
        long n = bridge.cycles() - cycles;
        long b = allocated(thread) - bytes;
        return String.format(Locale.ROOT, "  bridge thread: %,d bytes allocated over %,d snapshots, %,d a snapshot"
                + " (feed and the firings inline on it)", b, n, n == 0 ? 0 : b / n);
    }

    private static long allocated(long thread) {
        if (ManagementFactory.getThreadMXBean() instanceof com.sun.management.ThreadMXBean threads) {
            return threads.getThreadAllocatedBytes(thread);
        }
        return -1;
    }
}
