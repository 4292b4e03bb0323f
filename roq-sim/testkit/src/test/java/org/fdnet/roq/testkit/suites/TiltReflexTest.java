package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.Push;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.runtime.engine.DrivenClock;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The tilt reflex in networks/roq-reflex-bench.fdn: a push towards the hind-right corner while the hind-right leg
 * is in the air tips RoQ; the reflex sets that foot down at once, so it meets the ground sooner than with module
 * Reflex unloaded.
 */
@Timeout(120)
class TiltReflexTest {
    static final Path NETWORK = Path.of("..", "networks", "roq-reflex-bench.fdn");
    /** The crawl's first swing is hind-right's, 0.4–1.1 s; push towards its corner (back and right) at 0.6 s. */
    private static final Push TIP_TOWARDS_HIND_RIGHT = new Push(0.6, 0.1, 200, 225);
    /** A push towards the front-left corner, away from the hind-right foot in the air, at 0.6 s. */
    private static final Push TIP_TOWARDS_FRONT_LEFT = new Push(0.6, 0.1, 200, 45);
    private static final int FRONT_LEFT = 0;
    private static final int HIND_RIGHT = 3;
    private static final NodeRef BALANCE_SHIFT = NodeRef.parse("balance shift", "Balance");
    private static final NodeRef PRESS = NodeRef.parse("reflex press", "Reflex");
    /** roq-reflex-bench's brace: the stance feet's move along the fall and the crouch, m. */
    private static final double SHIFT = 0.08;
    private static final double CROUCH = 0.14;

    @Test
    void shouldSetTheSwingingFootDownWhenAPushTipsRoq() throws Exception {
        double withReflex = ticksUntilHindRightTouches(true);
        double without = ticksUntilHindRightTouches(false);
        assertThat(withReflex).as("ticks from the push to the hind-right foot's touchdown, with the reflex")
                .isLessThan(without * 0.8);
    }

    @Test
    void shouldMoveTheBodyAgainstThePushWhileItHoldsAndLetGoAfter() throws Exception {
        Course pushed = Course.flat().withStimuli(List.of(TIP_TOWARDS_HIND_RIGHT));
        try (RoqSimulator sim = RoqSimulator.open(pushed, SimMode.STEPPED);
             RuntimeNetwork net = RuntimeNetwork.start(NetworkRepository.load(NETWORK),
                     RuntimeOptions.defaults().drivenClock(new DrivenClock(0)))) {
            SimBridge bridge = SimBridge.stepped(net, sim, 0, 1);
            NodeRef press = NodeRef.parse("reflex press", "Reflex");
            bridge.run((int) TIP_TOWARDS_HIND_RIGHT.firstTick());
            double backRight = 0;
            double lowered = 0;
            for (int t = 0; t < 300; t++) {
                bridge.run(1);
                double[] c = net.controller().value(press).asDoubles();
                double[] shift = net.controller().value(BALANCE_SHIFT).asDoubles();
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
                bridge.run(1);
                if (Arrays.stream(net.controller().value(press).asDoubles()).allMatch(v -> v == 0)) {
                    letGo = t;
                }
            }
            assertThat(letGo).as("ms after the first 0.3 s until the correction is zero again").isBetween(0, 1499);
        }
    }

    @Test
    void shouldGiveBalancesLeanBackWhileItBraces() throws Exception {
        try (PushedWalk walk = new PushedWalk(TIP_TOWARDS_HIND_RIGHT)) {
            double lean = 0;
            double largestTotal = 0;
            int braced = 0;
            for (int t = 0; t < 300; t++) {
                walk.bridge.run(1);
                double[] c = walk.press();
                double[] shift = walk.shift();
                // fully braced (the crouch fades out after the hold) and the caught hind-right foot down
                if (c[3 * FRONT_LEFT + 2] == CROUCH && walk.bridge.lastSnapshot().footForce(HIND_RIGHT) > 20) {
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
    void shouldStepOnlyAFootOnTheSideRoqFallsTo() throws Exception {
        try (PushedWalk walk = new PushedWalk(TIP_TOWARDS_FRONT_LEFT)) {
            int caught = 0;
            double apart = 0;
            for (int t = 0; t < 300; t++) {
                walk.bridge.run(1);
                double[] c = walk.press();
                double[] shift = walk.shift();
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
    void shouldStayQuietOnAnUndisturbedWalk() throws Exception {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED);
             RuntimeNetwork net = RuntimeNetwork.start(NetworkRepository.load(NETWORK),
                     RuntimeOptions.defaults().drivenClock(new DrivenClock(0)))) {
            SimBridge bridge = SimBridge.stepped(net, sim, 0, 1);
            NodeRef press = NodeRef.parse("reflex press", "Reflex");
            double largest = 0;
            for (int i = 0; i < 1000; i++) {
                bridge.run(10);
                for (double v : net.controller().value(press).asDoubles()) {
                    largest = Math.max(largest, Math.abs(v));
                }
            }
            assertThat(largest).as("largest reflex correction over 10 s of walking, m").isZero();
            assertThat(bridge.lastSnapshot().groundTruthBodyPosition(0)).as("it walked").isGreaterThan(0.1);
        }
    }

    @Test
    void shouldRefuseAPeriodAndBadThresholdsNamingThem() throws Exception {
        NodeRef reflex = NodeRef.parse("tilt reflex", "Reflex");
        for (Parameter bad : List.of(new Parameter("period", ParameterType.LONG, "10"),
                new Parameter("tilt", ParameterType.DOUBLE, "-0.1"))) {
            NetworkInfo info = NetworkRepository.load(NETWORK);
            info.setParameters(reflex, List.of(bad));
            assertThatThrownBy(() -> RuntimeNetwork.start(info,
                    RuntimeOptions.defaults().drivenClock(new DrivenClock(0))).close())
                    .hasStackTraceContaining(bad.name());
        }
    }

    /** roq-reflex-bench walking on flat ground, stepped, up to the push. */
    private static final class PushedWalk implements AutoCloseable {
        private final RoqSimulator sim;
        private final RuntimeNetwork net;
        private final SimBridge bridge;

        PushedWalk(Push push) throws Exception {
            sim = RoqSimulator.open(Course.flat().withStimuli(List.of(push)), SimMode.STEPPED);
            net = RuntimeNetwork.start(NetworkRepository.load(NETWORK),
                    RuntimeOptions.defaults().drivenClock(new DrivenClock(0)));
            bridge = SimBridge.stepped(net, sim, 0, 1);
            bridge.run((int) push.firstTick());
        }

        double[] press() {
            return net.controller().value(PRESS).asDoubles();
        }

        double[] shift() {
            return net.controller().value(BALANCE_SHIFT).asDoubles();
        }

        @Override
        public void close() throws Exception {
            try (sim) {
                net.close();
            }
        }
    }

    private static double ticksUntilHindRightTouches(boolean reflex) throws Exception {
        Course pushed = Course.flat().withStimuli(List.of(TIP_TOWARDS_HIND_RIGHT));
        try (RoqSimulator sim = RoqSimulator.open(pushed, SimMode.STEPPED);
             RuntimeNetwork net = RuntimeNetwork.start(NetworkRepository.load(NETWORK),
                     RuntimeOptions.defaults().drivenClock(new DrivenClock(0)))) {
            SimBridge bridge = SimBridge.stepped(net, sim, 0, 1);
            bridge.run(1);
            if (!reflex) {
                assertThat(net.controller().unload("Reflex").executed()).isTrue();
            }
            bridge.run((int) TIP_TOWARDS_HIND_RIGHT.firstTick());
            for (int t = 0; t < 500; t++) {
                bridge.run(1);
                SensorSnapshot s = bridge.lastSnapshot();
                if (s.footForce(HIND_RIGHT) > 5) {
                    return t;
                }
            }
            return 500;
        }
    }
}
