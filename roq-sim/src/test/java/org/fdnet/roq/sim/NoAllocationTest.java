package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Test;

/** Reading snapshots and sending commands allocate nothing (the bridge calls them at the network's rate). */
class NoAllocationTest {
    @Test
    void shouldReadSnapshotsAndSendCommandsWithoutAllocating() {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            JointCommand command = new JointCommand();
            LoopStatistics stats = new LoopStatistics();
            exercise(sim, s, command, stats, 50_000); // let the JIT compile read/send
            long before = threads.getThreadAllocatedBytes(thread);
            exercise(sim, s, command, stats, 20_000);
            long allocated = threads.getThreadAllocatedBytes(thread) - before;
            assertThat(allocated).as("bytes allocated by 20,000 read + send + statistics").isLessThan(1024);
        }
    }

    private static void exercise(RoqSimulator sim, SensorSnapshot s, JointCommand command, LoopStatistics stats, int n) {
        for (int i = 0; i < n; i++) {
            sim.read(s);
            command.target(0, 0.001 * (i % 100));
            sim.send(command);
            if (i % 100 == 0) {
                sim.statistics(stats);
            }
        }
    }
}
