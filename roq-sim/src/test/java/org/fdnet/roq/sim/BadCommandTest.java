package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** NaN, out-of-range and stale commands are clamped or ignored and counted; the loop keeps the robot up. */
class BadCommandTest {
    @Test
    void shouldIgnoreNanTargetsAndCountThem() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            LoopStatistics stats = new LoopStatistics();
            sim.step(100);
            sim.read(s);
            JointCommand command = new JointCommand().target(1, Double.NaN).target(4, Double.POSITIVE_INFINITY)
                    .wheelSpeed(2, Double.NaN);
            sim.send(command);
            sim.step(1000);
            sim.read(s);
            sim.statistics(stats);
            assertThat(stats.commandsNan()).isEqualTo(3);
            assertThat(stats.commandsApplied()).isEqualTo(1);
            assertThat(s.jointAngle(1)).as("kept its previous target").isCloseTo(RoqGeometry.STANDING_POSE[1],
                    org.assertj.core.data.Offset.offset(0.05));
            assertThat(s.groundTruthBodyPosition(2)).isGreaterThan(RoqGeometry.standingHeight() - 0.03);
        }
    }

    @Test
    void shouldClampOutOfRangeTargetsAndCountThem() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimOptions.of(SimMode.STEPPED).withDropHeight(1.5))) {
            SensorSnapshot s = new SensorSnapshot();
            LoopStatistics stats = new LoopStatistics();
            int yaw = RoqGeometry.jointIndex(0, 0);
            sim.send(new JointCommand().target(yaw, 5.0).wheelSpeed(0, 1e6));
            sim.step(400);
            sim.read(s);
            sim.statistics(stats);
            assertThat(stats.commandsOutOfRange()).isEqualTo(2);
            assertThat(s.jointAngle(yaw)).as("clamped to the joint's upper limit").isCloseTo(RoqGeometry.jointMax(yaw),
                    org.assertj.core.data.Offset.offset(0.05));
            assertThat(s.wheelSpeed(0)).isLessThanOrEqualTo(RoqGeometry.WHEEL_MAX_SPEED + 0.5);
        }
    }

    @Test
    void shouldIgnoreStaleCommandsAndCountThem() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            LoopStatistics stats = new LoopStatistics();
            sim.step(1000);
            int knee = RoqGeometry.jointIndex(3, 2);
            sim.send(new JointCommand().target(knee, 1.0).basedOnTick(500));
            sim.step(500);
            sim.read(s);
            sim.statistics(stats);
            assertThat(stats.commandsStale()).isEqualTo(1);
            assertThat(stats.commandsApplied()).isZero();
            assertThat(s.jointAngle(knee)).as("the stale target was not applied")
                    .isCloseTo(RoqGeometry.STANDING_POSE[2], org.assertj.core.data.Offset.offset(0.05));
            assertThat(stats.badCommands()).isEqualTo(1);
        }
    }
}
