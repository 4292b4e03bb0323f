package org.acme.guard;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import org.fdnet.roq.testkit.Roq;
import org.fdnet.roq.testkit.RoqTest;
import org.fdnet.roq.testkit.SimulatedRoq;
import org.fdnet.runtime.Value;
import org.fdnet.testkit.FdnetTest;
import org.fdnet.testkit.NetworkFile;
import org.fdnet.testkit.TestNetwork;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;

class GuardedWalkTest {
    private static final String NETWORK = "networks/guarded-walk.fdn";

    @Nested
    @FdnetTest
    class Alone {
        @Test
        void shouldRaiseTheAlarmOnlyBeyondTheLimit(@NetworkFile(NETWORK) TestNetwork net) {
            net.set("attitude", Value.ofDoubles(0.1, -0.2));
            net.advance(Duration.ofMillis(100));
            net.assertValue("Guard/alarm").isFalse();
            net.set("attitude", Value.ofDoubles(0.1, -0.3));
            net.awaitValue("Guard/alarm", Value::asBoolean, Duration.ofMillis(200));
        }
    }

    @Nested
    @RoqTest
    class OnTheRobot {
        @Test
        void shouldWalkAFifthOfAMetreIntoRubbleSeed12WithoutAFallOrAnAlarm(
                @Roq(network = NETWORK, course = "rubble:12", noise = 3) SimulatedRoq roq) {
            roq.afterEachStep(r -> assertFalse(r.network().value("Guard/alarm").asBoolean(), "alarm at " + r.time()));
            roq.runUntil("0.2 m walked", r -> r.measures().distance() >= 0.2, Duration.ofSeconds(40));
            roq.assertThat().noFall();
        }
    }

    @Test
    void shouldGiveTheSameRobotStateForTheSameSeeds() {
        assertEquals(run(), run());
    }

    private static String run() {
        try (SimulatedRoq roq = SimulatedRoq.builder().network(Path.of(NETWORK)).course("rubble:12").noise(3).start()) {
            roq.runFor(Duration.ofSeconds(3));
            assertTrue(roq.measures().distance() > -0.1);
            return roq.stateHash();
        }
    }
}
