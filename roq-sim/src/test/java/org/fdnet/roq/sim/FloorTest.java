package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** Outside the course's heightfield there is a floor: a robot that drives off the edge lands, it does not sink. */
class FloorTest {
    @Test
    void shouldLandOnTheFloorWhenDrivingOffTheCourse() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat().withStart(1.7, 0), SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(500);
            sim.read(s);
            JointCommand drive = new JointCommand();
            for (int leg = 0; leg < RoqGeometry.LEGS; leg++) {
                drive.wheelSpeed(leg, 10.0);
            }
            sim.send(drive.basedOnTick(s.tick()));
            sim.step(6000);
            sim.read(s);
            assertThat(s.groundTruthBodyPosition(0)).as("drove off the course's end at x = 2").isGreaterThan(2.1);
            assertThat(s.groundTruthBodyPosition(2)).as("body height off the course")
                    .isGreaterThan(sim.heightfield().minHeight() - 0.05);
        }
    }
}
