package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The wheel mechanism: driven wheels roll the standing robot forward; braked wheels hold it. */
class WheelTest {
    @Test
    void shouldRollForwardOnDrivenWheelsAndStayPutOnBrakedOnes() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(500);
            sim.read(s);
            double x0 = s.groundTruthBodyPosition(0);
            sim.step(1000);
            sim.read(s);
            assertThat(Math.abs(s.groundTruthBodyPosition(0) - x0)).as("braked").isLessThan(0.002);

            JointCommand drive = new JointCommand();
            for (int leg = 0; leg < RoqGeometry.LEGS; leg++) {
                drive.wheelSpeed(leg, 5.0);
            }
            sim.send(drive.basedOnTick(s.tick()));
            sim.step(2000);
            sim.read(s);
            double travelled = s.groundTruthBodyPosition(0) - x0;
            assertThat(travelled).as("2 s at 5 rad/s on 3 cm wheels").isBetween(0.15, 0.32);
            assertThat(Math.abs(s.groundTruthYaw())).as("straight").isLessThan(0.05);
            assertThat(s.wheelSpeed(0)).isCloseTo(5.0, org.assertj.core.data.Offset.offset(0.5));
            assertThat(s.groundTruthBodyPosition(2)).as("still standing").isGreaterThan(RoqGeometry.standingHeight() - 0.03);
        }
    }
}
