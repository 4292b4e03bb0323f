package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** Stepped mode is bit-for-bit reproducible: the same course, noise seed and commands give the same state. */
class DeterminismTest {
    @Test
    void shouldReachTheSameStateHashInTwoSixtySecondRuns() throws Exception {
        long first = run();
        long second = run();
        assertThat(second).isEqualTo(first);
    }

    /** 60 s on rubble with sensor noise, the legs swaying on commands computed from the (noisy) snapshots. */
    private static long run() throws Exception {
        Course course = CourseLoader.resolve("fragile");
        try (RoqSimulator sim = RoqSimulator.open(course, SimOptions.of(SimMode.STEPPED).withNoise(7))) {
            SensorSnapshot s = new SensorSnapshot();
            JointCommand command = new JointCommand();
            for (int tick = 0; tick < 60_000; tick += 10) {
                sim.step(10);
                sim.read(s);
                for (int leg = 0; leg < RoqGeometry.LEGS; leg++) {
                    int yaw = RoqGeometry.jointIndex(leg, 0);
                    command.target(yaw, 0.2 * Math.sin(s.simTime() * 2 + leg) + 0.01 * s.jointAngle(yaw));
                }
                sim.send(command);
            }
            sim.read(s);
            assertThat(s.tick()).isEqualTo(60_000);
            return sim.stateHash();
        }
    }

    @Test
    void shouldDifferWhenTheNoiseSeedDiffers() {
        long[] hashes = new long[2];
        for (int seed = 0; seed < 2; seed++) {
            try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimOptions.of(SimMode.STEPPED).withNoise(seed))) {
                SensorSnapshot s = new SensorSnapshot();
                JointCommand command = new JointCommand();
                for (int i = 0; i < 100; i++) {
                    sim.step(10);
                    sim.read(s);
                    command.target(0, s.jointAngle(0) + 0.01);
                    sim.send(command);
                }
                hashes[seed] = sim.stateHash();
            }
        }
        assertThat(hashes[0]).as("noise reaches the state through the commands").isNotEqualTo(hashes[1]);
    }
}
