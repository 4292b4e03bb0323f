package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** In real-time mode the C thread ticks on its own, publishes snapshots, measures wake-ups and takes commands. */
class RealTimeLoopTest {
    @Test
    void shouldTickAndPublishOnItsOwnThread() throws InterruptedException {
        SensorSnapshot s = new SensorSnapshot();
        LoopStatistics stats = new LoopStatistics();
        long last;
        RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.REAL_TIME);
        try {
            long deadline = System.nanoTime() + 20_000_000_000L;
            while (sim.read(s) < 300 && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            assertThat(s.tick()).as("ticks within 20 s").isGreaterThanOrEqualTo(300);
            long before = s.tick();
            // A command is stale when the loop gets it over 100 ticks after the snapshot it was based on; on a loaded
            // machine this thread can stall that long between read and send, so it resends, as a controller would.
            JointCommand command = new JointCommand().target(0, 0.2);
            while (sim.statistics(stats).commandsApplied() == 0 && System.nanoTime() < deadline) {
                sim.read(s);
                sim.send(command);
                Thread.sleep(10);
            }
            long applied = s.tick();
            while (sim.read(s) < applied + 300 && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            sim.statistics(stats);
            assertThat(s.jointAngle(0)).as("the command reached the loop (applied %d, stale %d, tick %d)",
                    stats.commandsApplied(), stats.commandsStale(), s.tick())
                    .isCloseTo(0.2, org.assertj.core.data.Offset.offset(0.05));
            assertThat(stats.ticks()).isGreaterThanOrEqualTo(before + 300);
            assertThat(stats.latencySamples()).isGreaterThanOrEqualTo(before);
            assertThat(stats.commandsApplied()).isGreaterThanOrEqualTo(1);
            assertThat(stats.latencyPercentileNanos(50)).isPositive();
            assertThat(stats.latencyPercentileNanos(99)).isGreaterThanOrEqualTo(stats.latencyPercentileNanos(50));
            org.assertj.core.api.Assertions.assertThatThrownBy(() -> sim.step(1)).isInstanceOf(IllegalStateException.class)
                    .hasMessageContaining("STEPPED");
        } finally {
            sim.close();
        }
        last = sim.read(s);
        Thread.sleep(50);
        assertThat(sim.read(s)).as("stopped after close; the last snapshot stays readable").isEqualTo(last);
        org.assertj.core.api.Assertions.assertThatThrownBy(sim::stateHash).isInstanceOf(IllegalStateException.class)
                .hasMessageContaining("STEPPED");
    }
}
