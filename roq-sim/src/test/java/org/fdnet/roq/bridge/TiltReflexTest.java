package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
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
    private static final int HIND_RIGHT = 3;

    @Test
    void shouldSetTheSwingingFootDownWhenAPushTipsRoq() throws Exception {
        double withReflex = ticksUntilHindRightTouches(true);
        double without = ticksUntilHindRightTouches(false);
        assertThat(withReflex).as("ticks from the push to the hind-right foot's touchdown, with the reflex")
                .isLessThan(without * 0.8);
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
