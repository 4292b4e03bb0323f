package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/**
 * The real-time claims, as facts the loop exposes: 5 s of the loop tick at 1 kHz within 1 %, and as root (CI runs
 * as root) it holds SCHED_FIFO, mlockall and /dev/cpu_dma_latency.
 */
class RealTimeRateTest {
    @Test
    void shouldTickAtOneKilohertzAndHoldTheRealTimeSettingsItWasGiven() throws Exception {
        SensorSnapshot s = new SensorSnapshot();
        LoopStatistics stats = new LoopStatistics();
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.REAL_TIME)) {
            Thread.sleep(200);
            long t0 = System.nanoTime();
            long tick0 = sim.read(s);
            Thread.sleep(5000);
            long t1 = System.nanoTime();
            long tick1 = sim.read(s);
            sim.statistics(stats);
            double hertz = (tick1 - tick0) / ((t1 - t0) / 1e9);
            assertThat(hertz).as("ticks per wall second over 5 s (%d overruns, worst %d µs)", stats.overruns(),
                    stats.maxOverrunNanos() / 1000).isBetween(990.0, 1010.0);
            if (ThreadScheduling.runningAsRoot()) {
                assertThat(stats.schedFifo()).as("SCHED_FIFO obtained as root").isTrue();
                assertThat(stats.memoryLocked()).as("mlockall obtained as root").isTrue();
                assertThat(stats.dmaLatencyHeld()).as("/dev/cpu_dma_latency held as root").isTrue();
            }
        }
    }
}
