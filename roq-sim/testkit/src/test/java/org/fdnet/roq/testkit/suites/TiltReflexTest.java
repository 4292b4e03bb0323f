package org.fdnet.roq.testkit.suites;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.Push;
import org.fdnet.roq.testkit.SimulatedRoq;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The tilt reflex in networks/roq-reflex-bench.fdn, flat ground, sensor noise off: a push towards the hind-right
 * corner while the hind-right leg is in the air tips RoQ; the reflex sets that foot down at once, so it meets the
 * ground sooner than with module Reflex unloaded; it braces against the push and lets go after; it never steps across
 * the body and stays quiet on an undisturbed walk.
 */
@Timeout(120)
class TiltReflexTest {
    static final Path NETWORK = Path.of("../../networks/roq-reflex-bench.fdn");
    /** The crawl's first swing is hind-right's, 0.4–1.1 s; push towards its corner (back and right) at 0.6 s. */
    private static final Push TIP_TOWARDS_HIND_RIGHT = new Push(0.6, 0.1, 200, 225);
    /** A push towards the front-left corner, away from the hind-right foot in the air, at 0.6 s. */
    private static final Push TIP_TOWARDS_FRONT_LEFT = new Push(0.6, 0.1, 200, 45);
    private static final int FRONT_LEFT = 0;
    private static final int HIND_RIGHT = 3;
    private static final String BALANCE_SHIFT = "Balance/balance shift";
    private static final String PRESS = "Reflex/reflex press";
    /** roq-reflex-bench's brace: the stance feet's move along the fall and the crouch, m. */
    private static final double SHIFT = 0.08;
    private static final double CROUCH = 0.14;
    private static final Duration TICK = Duration.ofMillis(1);

    private static SimulatedRoq walk(String... unloaded) {
        return SimulatedRoq.builder().network(NETWORK).course("flat").withoutNoise().unload(unloaded).start();
    }

    /** roq-reflex-bench walking, pushed with {@code push}, run up to the plant's tick where the push begins. */
    private static SimulatedRoq pushedWalk(Push push) {
        SimulatedRoq roq = walk();
        roq.push(push);
        roq.advance(Duration.ofMillis(push.firstTick() - roq.snapshot().tick()));
        return roq;
    }

    private static double[] press(SimulatedRoq roq) {
        return roq.network().value(PRESS).asDoubles();
    }

    private static double[] shift(SimulatedRoq roq) {
        return roq.network().value(BALANCE_SHIFT).asDoubles();
    }

    @Test
    void shouldSetTheSwingingFootDownWhenAPushTipsRoq() {
        double withReflex = ticksUntilHindRightTouches(true);
        double without = ticksUntilHindRightTouches(false);
        // the reflex brings the caught foot down at least a fifth sooner than the crawl alone does
        assertThat(withReflex).as("ticks from the push to the hind-right foot's touchdown, with the reflex")
                .isLessThan(without * 0.8);
    }

    private static double ticksUntilHindRightTouches(boolean reflex) {
        try (SimulatedRoq roq = walk()) {
            if (!reflex) {
                roq.unload("Reflex");
            }
            roq.push(TIP_TOWARDS_HIND_RIGHT);
            roq.advance(Duration.ofMillis(TIP_TOWARDS_HIND_RIGHT.firstTick()));
            for (int t = 0; t < 500; t++) {
                roq.advance(TICK);
                if (roq.snapshot().footForce(HIND_RIGHT) > 5) {
                    return t;
                }
            }
            return 500;
        }
    }

    @Test
    void shouldMoveTheBodyAgainstThePushWhileItHoldsAndLetGoAfter() {
        try (SimulatedRoq roq = pushedWalk(TIP_TOWARDS_HIND_RIGHT)) {
            double backRight = 0;
            double lowered = 0;
            for (int t = 0; t < 300; t++) {
                roq.advance(TICK);
                double[] c = press(roq);
                double[] shift = shift(roq);
                // a stance foot moves the way RoQ falls (back and right): the body moves against it. What moves the
                // feet is what Integration adds to the gait's: Balance's shift and the reflex's correction.
                backRight = Math.max(backRight, -c[3 * FRONT_LEFT] - shift[3 * FRONT_LEFT]
                        - c[3 * FRONT_LEFT + 1] - shift[3 * FRONT_LEFT + 1]);
                lowered = Math.min(lowered, c[3 * HIND_RIGHT + 2] - c[3 * FRONT_LEFT + 2]);
            }
            assertThat(backRight).as("largest back-and-right move of the front-left foot while RoQ tips, m")
                    .isGreaterThan(0.05);
            assertThat(lowered).as("hind-right foot lowered below the stance feet, m").isLessThan(-0.01);
            int letGo = -1;
            for (int t = 0; t < 1500 && letGo < 0; t++) {
                roq.advance(TICK);
                if (Arrays.stream(press(roq)).allMatch(v -> v == 0)) {
                    letGo = t;
                }
            }
            assertThat(letGo).as("ms after the first 0.3 s until the correction is zero again").isBetween(0, 1499);
        }
    }

    @Test
    void shouldGiveBalancesLeanBackWhileItBraces() {
        try (SimulatedRoq roq = pushedWalk(TIP_TOWARDS_HIND_RIGHT)) {
            double lean = 0;
            double largestTotal = 0;
            int braced = 0;
            for (int t = 0; t < 300; t++) {
                roq.advance(TICK);
                double[] c = press(roq);
                double[] shift = shift(roq);
                // fully braced (the crouch fades out after the hold) and the caught hind-right foot down
                if (c[3 * FRONT_LEFT + 2] == CROUCH && roq.snapshot().footForce(HIND_RIGHT) > 20) {
                    braced++;
                    lean = Math.max(lean, Math.hypot(shift[3 * FRONT_LEFT], shift[3 * FRONT_LEFT + 1]));
                    largestTotal = Math.max(largestTotal, Math.hypot(shift[3 * FRONT_LEFT] + c[3 * FRONT_LEFT],
                            shift[3 * FRONT_LEFT + 1] + c[3 * FRONT_LEFT + 1]));
                }
            }
            assertThat(braced).as("ms fully braced with the caught foot down after the push").isGreaterThan(50);
            assertThat(lean).as("Balance's lean while the reflex braces, m").isGreaterThan(0.1);
            assertThat(largestTotal).as("front-left foot's move from the gait's place (lean + brace), m: the brace's "
                    + SHIFT + " m only").isLessThan(SHIFT + 0.005);
        }
    }

    @Test
    void shouldStepOnlyAFootOnTheSideRoqFallsTo() {
        try (SimulatedRoq roq = pushedWalk(TIP_TOWARDS_FRONT_LEFT)) {
            int caught = 0;
            double apart = 0;
            for (int t = 0; t < 300; t++) {
                roq.advance(TICK);
                double[] c = press(roq);
                double[] shift = shift(roq);
                if (c[3 * HIND_RIGHT + 2] < c[3 * FRONT_LEFT + 2]) { // hind-right, in the air, set down
                    caught++;
                    // no horizontal correction, or (once it is down) only Balance's lean given back: lean + it = 0
                    apart = Math.max(apart, Math.min(Math.hypot(c[3 * HIND_RIGHT], c[3 * HIND_RIGHT + 1]),
                            Math.hypot(c[3 * HIND_RIGHT] + shift[3 * HIND_RIGHT],
                                    c[3 * HIND_RIGHT + 1] + shift[3 * HIND_RIGHT + 1])));
                }
            }
            assertThat(caught).as("ms the hind-right foot was set down after a push to the front-left").isPositive();
            assertThat(apart).as("hind-right foot's move from the gait's place, m: no step across the body")
                    .isLessThan(0.005);
        }
    }

    @Test
    void shouldStayQuietOnAnUndisturbedWalk() {
        try (SimulatedRoq roq = walk()) {
            double[] largest = new double[1];
            roq.afterEachStep(r -> {
                for (double v : press(r)) {
                    largest[0] = Math.max(largest[0], Math.abs(v));
                }
            });
            roq.runFor(Duration.ofSeconds(10));
            assertThat(largest[0]).as("largest reflex correction over 10 s of walking, m").isZero();
            assertThat(roq.snapshot().groundTruthBodyPosition(0)).as("it walked").isGreaterThan(0.1);
        }
    }

    @Test
    void shouldRefuseAPeriodAndBadThresholdsNamingThem() throws Exception {
        NodeRef reflex = NodeRef.parse("tilt reflex", "Reflex");
        for (Parameter bad : List.of(new Parameter("period", ParameterType.LONG, "10"),
                new Parameter("tilt", ParameterType.DOUBLE, "-0.1"))) {
            NetworkInfo info = NetworkRepository.load(NETWORK);
            info.setParameters(reflex, List.of(bad));
            assertThatThrownBy(() -> SimulatedRoq.builder().network(info).start().close())
                    .hasStackTraceContaining(bad.name());
        }
    }
}
