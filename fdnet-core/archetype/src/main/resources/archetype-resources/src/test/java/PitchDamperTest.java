package ${package};

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.fdnet.runtime.Value;
import org.fdnet.testkit.FdnetTest;
import org.fdnet.testkit.NetworkFile;
import org.fdnet.testkit.TestNetwork;
import org.junit.jupiter.api.Test;

/**
 * The Lab module of networks/lab-walk.fdn on its own, without the robot: the test sets RoQ's inclinometer by hand
 * and reads the correction, on a driven clock (simulated time, no sleeping).
 */
@FdnetTest
class PitchDamperTest {
    private static final String NETWORK = "networks/lab-walk.fdn";
    private static final String CORRECTION = "Lab/pitch correction";

    @Test
    void shouldRaiseTheFootAheadAndLowerTheFootBehindWhenTheNoseDips(@NetworkFile(NETWORK) TestNetwork net) {
        net.set("attitude", Value.ofDoubles(0, 0.02));              // roll, pitch (rad): nose slightly down
        net.awaitValue(CORRECTION, v -> v.element(2) != 0, Duration.ofSeconds(1));

        Value feet = net.value("gait feet");
        Value correction = net.value(CORRECTION);
        for (int leg = 0; leg < 4; leg++) {
            double x = feet.element(3 * leg);
            double z = correction.element(3 * leg + 2);
            assertEquals(-Math.signum(x), Math.signum(z), "leg " + leg + " at x = " + x + " m moved by " + z + " m");
            assertTrue(Math.abs(z) <= 0.01, "leg " + leg + " moved by " + z + " m, beyond the limit");
        }
    }

    @Test
    void shouldNeverMoveAFootFartherThanItsLimit(@NetworkFile(NETWORK) TestNetwork net) {
        net.set("attitude", Value.ofDoubles(0, 0.6));               // a fall's pitch
        net.advance(Duration.ofMillis(200));

        Value correction = net.value(CORRECTION);
        for (int leg = 0; leg < 4; leg++) {
            assertEquals(0.01, Math.abs(correction.element(3 * leg + 2)), 1e-12, "leg " + leg);
        }
        assertTrue(net.relationFailures().isEmpty(), () -> "failed: " + net.relationFailures());
    }

    @Test
    void shouldFailTheDamperRatherThanPassACorrectionBeyondTheBound(@NetworkFile(NETWORK) TestNetwork net) {
        net.setParameter("Lab/damp pitch", "limit", "0.03");         // the Data's bound is 0.02 m
        net.set("attitude", Value.ofDoubles(0, 0.6));
        net.advance(Duration.ofMillis(200));

        assertEquals(1, net.relationFailures().size(), () -> "failed: " + net.relationFailures());
        assertTrue(net.relationFailures().get(0).toString().contains("damp pitch"),
                () -> "failed: " + net.relationFailures());
        for (int leg = 0; leg < 4; leg++) {
            assertTrue(Math.abs(net.value(CORRECTION).element(3 * leg + 2)) <= 0.02, "leg " + leg);
        }
    }
}
