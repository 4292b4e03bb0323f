package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.runtime.engine.DrivenClock;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** networks/roq-walk.fdn on the simulated RoQ, stepped, flat ground. */
@Timeout(120)
class RoqWalkTest {
    private static final Path WALK = Path.of("..", "networks", "roq-walk.fdn");

    private static RuntimeNetwork start() throws Exception {
        return RuntimeNetwork.start(NetworkRepository.load(WALK), RuntimeOptions.defaults().drivenClock(new DrivenClock(0)));
    }

    private static double x(SimBridge b) {
        return b.lastSnapshot().groundTruthBodyPosition(0);
    }

    private static boolean fallen(RuntimeNetwork net) {
        return net.controller().value(NodeRef.parse("fallen", "main")).asBoolean();
    }

    @Test
    void shouldWalkAtLeastOneMetreInSixtySecondsOnFlatGroundWithoutFalling() throws Exception {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED); RuntimeNetwork net = start()) {
            SimBridge bridge = SimBridge.stepped(net, sim, 0, 1);
            bridge.run(1);
            double x0 = x(bridge);
            bridge.run(60_000);
            assertThat(fallen(net)).isFalse();
            assertThat(x(bridge) - x0).as("metres walked forward").isGreaterThanOrEqualTo(1.0);
            assertThat(Math.abs(bridge.lastSnapshot().roll())).isLessThan(0.1);
            assertThat(Math.abs(bridge.lastSnapshot().pitch())).isLessThan(0.1);
        }
    }

    @Test
    void shouldStopWhileGaitIsHeldAndWalkOnWhenItIsResumed() throws Exception {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED); RuntimeNetwork net = start()) {
            SimBridge bridge = SimBridge.stepped(net, sim, 0, 1);
            bridge.run(10_000);
            assertThat(net.controller().hold("Gait").executed()).isTrue();
            bridge.run(1_000);
            double held = x(bridge);
            bridge.run(10_000);
            // no step (a stride is 0.15 m); Balance, closed on the soles' centre of pressure, still centres the body
            assertThat(Math.abs(x(bridge) - held)).as("metres moved in 10 s with Gait held").isLessThan(0.05);
            assertThat(net.controller().resume("Gait").executed()).isTrue();
            double resumed = x(bridge);
            bridge.run(15_000);
            assertThat(x(bridge) - resumed).as("metres walked in 15 s after resuming (measured 0.17)").isGreaterThan(0.1);
            assertThat(fallen(net)).isFalse();
        }
    }

    @Test
    void shouldGiveTheSameEventLogForTwoSteppedRunsOfTheSameNetworkAndCourse() throws Exception {
        assertThat(steppedEventLogHash()).isEqualTo(steppedEventLogHash());
    }

    private static String steppedEventLogHash() throws Exception {
        org.fdnet.event.MemoryEventSink sink = new org.fdnet.event.MemoryEventSink();
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED);
             RuntimeNetwork net = RuntimeNetwork.start(NetworkRepository.load(WALK),
                     RuntimeOptions.defaults().drivenClock(new DrivenClock(1_000_000_000_000L)).sink(sink))) {
            SimBridge.stepped(net, sim, 1_000_000_000_000L, 1).run(3_000);
        }
        java.security.MessageDigest sha = java.security.MessageDigest.getInstance("SHA-256");
        assertThat(sink.size()).isGreaterThan(3_000);
        for (org.fdnet.event.NetworkEvent e : sink.events()) {
            sha.update(e.toString().getBytes(java.nio.charset.StandardCharsets.UTF_8));
        }
        return java.util.HexFormat.of().formatHex(sha.digest());
    }
}
