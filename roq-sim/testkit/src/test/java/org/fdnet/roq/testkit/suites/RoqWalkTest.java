package org.fdnet.roq.testkit.suites;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import org.fdnet.roq.testkit.Roq;
import org.fdnet.roq.testkit.RoqTest;
import org.fdnet.roq.testkit.SimulatedRoq;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** networks/roq-walk.fdn on the simulated RoQ, flat ground, sensor noise off: it walks, stops when held, repeats. */
@RoqTest
@Timeout(120)
class RoqWalkTest {
    private static final String WALK = "../../networks/roq-walk.fdn";

    private static double x(SimulatedRoq roq) {
        return roq.snapshot().groundTruthBodyPosition(0);
    }

    @Test
    void shouldWalkAtLeastOneMetreInSixtySecondsOnFlatGroundWithoutFalling(
            @Roq(network = WALK, sensorNoise = false) SimulatedRoq roq) {
        roq.runFor(Duration.ofSeconds(60));

        // it walks about 1.5 m; 1 m is a third below
        roq.assertThat().noFall().walkedAtLeast(1.0);
        // upright at the end: twice the bound RoqStandTest sets for standing still
        assertThat(Math.abs(roq.snapshot().roll())).isLessThan(0.1);
        assertThat(Math.abs(roq.snapshot().pitch())).isLessThan(0.1);
    }

    @Test
    void shouldStopWhileGaitIsHeldAndWalkOnWhenItIsResumed(@Roq(network = WALK, sensorNoise = false) SimulatedRoq roq) {
        roq.runFor(Duration.ofSeconds(10));
        assertThat(roq.network().controller().hold("Gait").executed()).isTrue();
        roq.runFor(Duration.ofSeconds(1));
        double held = x(roq);

        roq.runFor(Duration.ofSeconds(10));

        // no step (a stride is 0.15 m); Balance, closed on the soles' centre of pressure, still centres the body
        assertThat(Math.abs(x(roq) - held)).as("metres moved in 10 s with Gait held").isLessThan(0.05);
        assertThat(roq.network().controller().resume("Gait").executed()).isTrue();
        double resumed = x(roq);
        roq.runFor(Duration.ofSeconds(15));
        assertThat(x(roq) - resumed).as("metres walked in 15 s after resuming (measured 0.17)").isGreaterThan(0.1);
        roq.assertThat().noFall();
    }

    @Test
    void shouldGiveTheSameEventLogAndStateForTwoRunsOfTheSameNetworkAndCourse() {
        String[] first = eventLogAndStateAfterThreeSeconds();
        String[] second = eventLogAndStateAfterThreeSeconds();

        assertThat(second).containsExactly(first);
    }

    private static String[] eventLogAndStateAfterThreeSeconds() {
        try (SimulatedRoq roq = SimulatedRoq.builder().network(Path.of(WALK)).course("flat").withoutNoise().start()) {
            roq.runFor(Duration.ofSeconds(3));
            assertThat(roq.network().events()).hasSizeGreaterThan(3_000);
            return new String[] {roq.eventLogHash(), roq.stateHash()};
        }
    }
}
