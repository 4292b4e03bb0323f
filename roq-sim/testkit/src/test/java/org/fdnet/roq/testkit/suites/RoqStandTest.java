package org.fdnet.roq.testkit.suites;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.time.Duration;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.testkit.Roq;
import org.fdnet.roq.testkit.RoqTest;
import org.fdnet.roq.testkit.SimulatedRoq;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * networks/roq-stand.fdn on the simulated RoQ, flat ground, sensor noise off: the network, not the simulator, holds
 * the posture.
 */
@RoqTest
@Timeout(60)
class RoqStandTest {
    private static final String STAND = "../../networks/roq-stand.fdn";
    /** The body height roq-stand asks for, m. */
    private static final double WANTED_HEIGHT = 0.27;

    @Test
    void shouldStandTenSecondsAtTheHeightTheNetworkAsksForWithoutFalling(
            @Roq(network = STAND, sensorNoise = false) SimulatedRoq roq) {
        roq.runFor(Duration.ofSeconds(10));

        SensorSnapshot s = roq.snapshot();
        assertThat(s.simTime()).isCloseTo(10.0, offset(0.01));
        roq.assertThat().noFall();
        // level: 0.05 rad is one foot 2 cm higher than the opposite one across RoQ's 0.43 m diagonal
        assertThat(Math.abs(s.roll())).isLessThan(0.05);
        assertThat(Math.abs(s.pitch())).isLessThan(0.05);
        assertThat(s.groundTruthBodyPosition(2)).as("body height").isCloseTo(WANTED_HEIGHT, offset(0.015));
        assertThat(roq.network().value("attitude").length()).isEqualTo(2);
    }

    @Test
    void shouldKeepTheSimulatorsStandingHeightWhenModuleLegsIsUnloaded(
            @Roq(network = STAND, sensorNoise = false, unload = "Legs") SimulatedRoq roq) {
        roq.runFor(Duration.ofSeconds(3));

        assertThat(roq.snapshot().groundTruthBodyPosition(2)).as("no inverse kinematics, no raising")
                .isCloseTo(RoqGeometry.standingHeight(), offset(0.015));
    }
}
