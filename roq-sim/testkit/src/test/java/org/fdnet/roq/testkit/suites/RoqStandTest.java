package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.nio.file.Path;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.runtime.engine.DrivenClock;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** networks/roq-stand.fdn on the simulated RoQ, stepped: the network, not the simulator, holds the posture. */
@Timeout(60)
class RoqStandTest {
    private static final Path STAND = Path.of("..", "networks", "roq-stand.fdn");
    private static final double WANTED_HEIGHT = 0.27;

    private static RuntimeNetwork start() throws Exception {
        return RuntimeNetwork.start(NetworkRepository.load(STAND), RuntimeOptions.defaults().drivenClock(new DrivenClock(0)));
    }

    @Test
    void shouldStandTenSecondsAtTheHeightTheNetworkAsksForWithoutFalling() throws Exception {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED); RuntimeNetwork net = start()) {
            SimBridge bridge = SimBridge.stepped(net, sim, 0, 1);
            bridge.run(10_000);
            SensorSnapshot s = bridge.lastSnapshot();
            assertThat(s.simTime()).isCloseTo(10.0, offset(0.01));
            assertThat(net.controller().value(NodeRef.parse("fallen", "main")).asBoolean()).isFalse();
            assertThat(Math.abs(s.roll())).isLessThan(0.05);
            assertThat(Math.abs(s.pitch())).isLessThan(0.05);
            assertThat(s.groundTruthBodyPosition(2)).as("body height").isCloseTo(WANTED_HEIGHT, offset(0.015));
            assertThat(net.controller().value(NodeRef.parse("attitude", "main")).length()).isEqualTo(2);
        }
    }

    @Test
    void shouldKeepTheSimulatorsStandingHeightWhenModuleLegsIsUnloaded() throws Exception {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED); RuntimeNetwork net = start()) {
            net.controller().unload("Legs");
            SimBridge bridge = SimBridge.stepped(net, sim, 0, 1);
            bridge.run(3_000);
            assertThat(bridge.lastSnapshot().groundTruthBodyPosition(2)).as("no inverse kinematics, no raising")
                    .isCloseTo(RoqGeometry.standingHeight(), offset(0.015));
        }
    }
}
