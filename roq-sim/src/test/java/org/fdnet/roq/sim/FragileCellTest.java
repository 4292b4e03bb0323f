package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A fragile cell under the front-left foot bears the robot standing on four feet and a brief press (a probing
 * tap), and breaks when the foot carries the robot's weight on the diagonal FL–HR.
 */
class FragileCellTest {
    static final double STRENGTH = 65;

    private static Course courseWithCellUnderFrontLeftFoot() {
        double[] foot = RoqGeometry.footInBody(0, RoqGeometry.STANDING_POSE[0], RoqGeometry.STANDING_POSE[1],
                RoqGeometry.STANDING_POSE[2], new double[3]);
        return Course.flat().withFragileCells(List.of(new FragileCell(foot[0], foot[1], 0.16, 0.16, 0.03, STRENGTH)));
    }

    @Test
    void shouldSurviveATapAndBreakUnderALoadedFoot() {
        try (RoqSimulator sim = RoqSimulator.open(courseWithCellUnderFrontLeftFoot(), SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(1000);
            sim.read(s);
            assertThat(s.footForce(0)).as("standing load on the cell").isBetween(20.0, STRENGTH);
            assertThat(s.isCellBroken(0)).as("bears the robot standing on four feet").isFalse();

            int frontLeftLift = RoqGeometry.jointIndex(0, 1);
            JointCommand tap = new JointCommand().target(frontLeftLift, RoqGeometry.STANDING_POSE[1] - 0.15);
            double peak = 0;
            sim.send(tap);
            for (int t = 0; t < 60; t++) {
                sim.step(1);
                sim.read(s);
                peak = Math.max(peak, s.footForce(0));
            }
            sim.send(new JointCommand());
            sim.step(1000);
            sim.read(s);
            assertThat(peak).as("the tap pressed harder than the cell's strength, briefly").isGreaterThan(STRENGTH);
            assertThat(s.isCellBroken(0)).as("survives the tap").isFalse();
            assertThat(s.brokenCellCount()).isZero();

            JointCommand diagonal = new JointCommand()
                    .target(RoqGeometry.jointIndex(1, 1), RoqGeometry.STANDING_POSE[1] + 0.3)
                    .target(RoqGeometry.jointIndex(2, 1), RoqGeometry.STANDING_POSE[1] + 0.3);
            double heightBefore = s.groundTruthBodyPosition(2);
            sim.send(diagonal);
            sim.step(1000);
            sim.read(s);
            assertThat(s.isCellBroken(0)).as("breaks under the loaded foot").isTrue();
            assertThat(s.brokenCellCount()).isEqualTo(1);
            assertThat(s.groundTruthBodyPosition(2)).as("the foot went down with it").isLessThan(heightBefore - 0.01);
        }
    }
}
