package ${package};

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.fdnet.roq.testkit.Roq;
import org.fdnet.roq.testkit.RoqTest;
import org.fdnet.roq.testkit.SimulatedRoq;
import org.junit.jupiter.api.Test;

/**
 * networks/lab-walk.fdn on the simulated RoQ, stepped: the same run every time (course, sensor noise and the
 * network's clock are all seeded), never waiting for the clock. A failing test prints the command that replays
 * its recording and the path of a picture of the robot at the failure.
 */
@RoqTest
class LabWalkTest {
    @Test
    void shouldWalkLevelGroundForTwentySecondsWithoutAFall(
            @Roq(network = "networks/lab-walk.fdn", course = "flat", noise = 7) SimulatedRoq roq) {
        roq.runFor(Duration.ofSeconds(20));

        // 0.34 m: 20 % below the median distance over noise seeds 1, 2, 3, 11, 23 and 42 (0.43 m, all within
        // 0.427-0.450 m); 0.2 rad: five times the largest tilt those runs had (0.042 rad).
        roq.assertThat().noFall().walkedAtLeast(0.34).tiltAtMost(0.2);
        assertTrue(roq.network().value("Lab/pitch correction") != null, "the Lab's correction was never written");
    }
}
