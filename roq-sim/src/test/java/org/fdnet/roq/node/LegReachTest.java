package org.fdnet.roq.node;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static org.fdnet.roq.sim.RoqGeometry.HIP_POSITION;
import static org.fdnet.roq.sim.RoqGeometry.JOINT_MAX;
import static org.fdnet.roq.sim.RoqGeometry.LEGS;
import static org.fdnet.roq.sim.RoqGeometry.maxJointTorque;

import java.util.Random;
import org.junit.jupiter.api.Test;

class LegReachTest {
    private static final double Z = -0.24;

    private final LegReach reach = new LegReach(0.1, 0.1);

    @Test
    void aFootStraightOutFromItsHipIsWithinReachOnEverySide() {
        for (int leg = 0; leg < LEGS; leg++) {
            double side = Math.signum(HIP_POSITION[leg][1]);
            assertThat(reach.reaches(leg, HIP_POSITION[leg][0], HIP_POSITION[leg][1] + side * 0.15)).isTrue();
            assertThat(reach.reaches(leg, HIP_POSITION[leg][0], HIP_POSITION[leg][1] - side * 0.15)).isFalse();
        }
    }

    @Test
    void aFootMayStandAsFarAheadAsTheYawRangeLessItsMarginPoints() {
        assertThat(reach.along(0.15)).isCloseTo(0.15 * Math.tan(JOINT_MAX[0] - 0.1), within(1e-12));
        assertThat(reach.along(0.25)).isGreaterThan(reach.along(0.15));
        assertThat(reach.reaches(0, 0.25 + 0.99 * reach.along(0.15), 0.30)).isTrue();
        assertThat(reach.reaches(0, 0.25 + 1.01 * reach.along(0.15), 0.30)).isFalse();
        assertThat(reach.reaches(0, 0.25 - 1.01 * reach.along(0.15), 0.30)).isFalse();
    }

    @Test
    void aFootNearUnderItsHipIsOutOfReachWhateverItsYaw() {
        assertThat(reach.along(0.05)).isZero();
        assertThat(reach.reaches(3, -0.25, -0.20)).isFalse();
    }

    @Test
    void aFootOutOfTheWedgeIsOneTheInverseKinematicsWouldClampAndInsideOneItWouldNot() {
        double[] angles = new double[3];
        LegReach bare = new LegReach(0, 0.1);
        assertThat(LegInverseKinematics.solve(1, 0.25 + 1.05 * bare.along(0.15), -0.30, Z, angles, 0)).isTrue();
        assertThat(LegInverseKinematics.solve(1, 0.25 + 0.95 * bare.along(0.15), -0.30, Z, angles, 0)).isFalse();
    }

    @Test
    void theWedgesHalfPlanesHoldExactlyWhereTheFootIsWithinReach() {
        Random random = new Random(7);
        for (int i = 0; i < 2000; i++) {
            int leg = random.nextInt(LEGS);
            double x = HIP_POSITION[leg][0] + (random.nextDouble() - 0.5) * 0.8;
            double y = HIP_POSITION[leg][1] + (random.nextDouble() - 0.5) * 0.8;
            boolean inside = true;
            for (double[] row : reach.wedge(leg)) {
                inside &= row[0] * x + row[1] * y <= row[2];
            }
            assertThat(inside).as("leg %d at (%f, %f)", leg, x, y).isEqualTo(reach.reaches(leg, x, y));
        }
    }

    @Test
    void aLegCarriesMostWithItsFootPartWayOutAndLessNearUnderItsHipOrFarOut() {
        double near = LegReach.capacity(0, 0.25, 0.15 + 0.08, Z);
        double middle = LegReach.capacity(0, 0.25, 0.15 + 0.20, Z);
        double far = LegReach.capacity(0, 0.25, 0.15 + 0.30, Z);
        assertThat(middle).isGreaterThan(near).isGreaterThan(far);
        // far out the lift motor holds the load at the foot's distance from the lift axis (coxa 0.06 m)
        assertThat(far).isCloseTo(maxJointTorque() / (0.30 - 0.06), within(1e-9));
    }
}
