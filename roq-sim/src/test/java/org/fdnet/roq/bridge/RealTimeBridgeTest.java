package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.nio.file.Path;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.roq.sim.ThreadScheduling;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * networks/roq-stand.fdn on the wall clock, joined to the real-time simulator by the bridge's own thread, which runs
 * under SCHED_FIFO when the system allows (as root).
 */
@Timeout(60)
class RealTimeBridgeTest {
    @Test
    void shouldFeedTheSensorsAndApplyTheNetworksTargetsInRealTime() throws Exception {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.REAL_TIME);
             RuntimeNetwork net = RuntimeNetwork.start(NetworkRepository.load(Path.of("..", "networks", "roq-stand.fdn")),
                     RuntimeOptions.defaults());
             SimBridge bridge = SimBridge.realTime(net, sim)) {
            SensorSnapshot s = new SensorSnapshot();
            long deadline = System.nanoTime() + 30_000_000_000L;
            // the network raises the body to 0.27 m over 1 s of its time; allow a loaded machine its delays
            do {
                Thread.sleep(200);
                sim.read(s);
            } while (Math.abs(s.groundTruthBodyPosition(2) - 0.27) > 0.015 && System.nanoTime() < deadline);
            assertThat(s.groundTruthBodyPosition(2)).as("body height").isCloseTo(0.27, offset(0.015));
            assertThat(bridge.cycles()).isPositive();
            assertThat(ThreadScheduling.ofThreadNamed("roq-bridge").fifo())
                    .as("the bridge's thread under SCHED_FIFO, as root").isEqualTo(ThreadScheduling.runningAsRoot());
            assertThat(net.controller().value(NodeRef.parse("attitude", "main")).length()).isEqualTo(2);
            assertThat(net.controller().value(NodeRef.parse("fallen", "main")).asBoolean()).isFalse();
        }
    }
}
