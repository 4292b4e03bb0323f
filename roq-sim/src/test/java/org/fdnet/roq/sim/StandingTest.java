package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The robot with fixed standing targets stays up, and settles when dropped. */
class StandingTest {
    @Test
    void shouldHoldTheStandingPoseForTenSeconds() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            double height = RoqGeometry.standingHeight();
            for (int second = 1; second <= 10; second++) {
                sim.step(1000);
                sim.read(s);
                assertThat(s.groundTruthBodyPosition(2)).as("body height at %d s", second).isBetween(height - 0.02, height + 0.01);
                assertThat(Math.abs(s.roll())).as("roll at %d s", second).isLessThan(0.02);
                assertThat(Math.abs(s.pitch())).as("pitch at %d s", second).isLessThan(0.02);
                assertThat(Math.hypot(s.groundTruthBodyPosition(0), s.groundTruthBodyPosition(1)))
                        .as("drift at %d s", second).isLessThan(0.01);
                for (int leg = 0; leg < RoqGeometry.LEGS; leg++) {
                    assertThat(s.footContact(leg)).as("leg %d touches at %d s", leg, second).isTrue();
                }
            }
            assertThat(s.tick()).isEqualTo(10_000);
            assertThat(s.simTime()).isCloseTo(10.0, org.assertj.core.data.Offset.offset(1e-9));
            double weight = RoqGeometry.TOTAL_MASS * 9.81;
            double soles = s.footForce(0) + s.footForce(1) + s.footForce(2) + s.footForce(3);
            assertThat(soles).as("the soles carry the robot's weight").isCloseTo(weight, org.assertj.core.data.Percentage.withPercentage(5));
        }
    }

    @Test
    void shouldSettleWhenDroppedFromTwentyCentimetres() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimOptions.of(SimMode.STEPPED).withDropHeight(0.2))) {
            SensorSnapshot s = new SensorSnapshot();
            sim.read(s);
            double height = RoqGeometry.standingHeight();
            assertThat(s.groundTruthBodyPosition(2)).isGreaterThan(height + 0.19);
            sim.step(100);
            sim.read(s);
            for (int leg = 0; leg < RoqGeometry.LEGS; leg++) {
                assertThat(s.footContact(leg)).as("leg %d in the air after 0.1 s", leg).isFalse();
            }
            sim.step(2900);
            sim.read(s);
            double z = s.groundTruthBodyPosition(2);
            sim.step(500);
            sim.read(s);
            assertThat(Math.abs(s.groundTruthBodyPosition(2) - z)).as("still after 3 s").isLessThan(0.002);
            assertThat(s.groundTruthBodyPosition(2)).as("standing again").isBetween(height - 0.03, height + 0.01);
            assertThat(Math.abs(s.roll()) + Math.abs(s.pitch())).isLessThan(0.03);
            for (int leg = 0; leg < RoqGeometry.LEGS; leg++) {
                assertThat(s.footContact(leg)).as("leg %d down", leg).isTrue();
            }
        }
    }
}
