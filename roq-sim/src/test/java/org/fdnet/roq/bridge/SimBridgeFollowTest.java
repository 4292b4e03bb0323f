package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.node.JointTargets;
import org.fdnet.roq.node.RoqSensor;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.Push;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.runtime.NetworkEdits;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.DrivenClock;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The bridge follows the network (sensors and targets added, removed, loaded, unloaded live) and observes
 * JointTargets: every changed value is sent, stamped with the tick of the snapshot it was computed from.
 */
@Timeout(120)
class SimBridgeFollowTest {
    private static final Path NETWORK = Path.of("..", "networks", "roq-reflex-bench.fdn");
    private static final NodeRef TARGETS = NodeRef.parse("joint targets", "main");
    private static final NodeRef IK = NodeRef.parse("inverse kinematics", "Legs");

    private static RuntimeNetwork start() throws Exception {
        return RuntimeNetwork.start(NetworkRepository.load(NETWORK),
                RuntimeOptions.defaults().drivenClock(new DrivenClock(0)));
    }

    private static NodeInfo sensor(String name, String channel) {
        return NodeInfo.data(name, RoqSensor.class.getName(), Parameter.named("channel", channel));
    }

    @Test
    void shouldFeedASensorAddedOrLoadedLiveAndDropOneDeletedOrUnloadedAtOnce() throws Exception {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED);
             RuntimeNetwork net = start();
             SimBridge bridge = SimBridge.stepped(net, sim, 0, 1)) {
            bridge.run(10);
            int fed = bridge.sensorsFed();
            NodeRef accel = NodeRef.parse("imu accel", "main");
            assertThat(net.controller().apply("add", NetworkEdits.addNode("main", sensor("imu accel", "imu_accel")))
                    .executed()).isTrue();
            assertThat(bridge.sensorsFed()).isEqualTo(fed + 1);
            bridge.run(1);
            Value v = net.controller().value(accel);
            assertThat(v.tick()).as("fed from the next snapshot, stamped with it").isEqualTo(bridge.lastSnapshot().tick());
            assertThat(v.element(2)).as("gravity").isGreaterThan(9);

            assertThat(net.controller().apply("delete", NetworkEdits.deleteNode(accel)).executed()).isTrue();
            assertThat(bridge.sensorsFed()).isEqualTo(fed);
            bridge.run(5);

            NodeRef extra = NodeRef.parse("extra gyro", "Extra");
            assertThat(net.controller().apply("module", NetworkEdits.all(NetworkEdits.addModule("Extra", true),
                    NetworkEdits.addNode("Extra", sensor("extra gyro", "imu_gyro")))).executed()).isTrue();
            assertThat(net.controller().load("Extra").executed()).isTrue();
            bridge.run(1);
            assertThat(net.controller().value(extra).tick()).isEqualTo(bridge.lastSnapshot().tick());
            assertThat(net.controller().unload("Extra").executed()).isTrue();
            assertThat(bridge.sensorsFed()).as("dropped at once").isEqualTo(fed);
            bridge.run(5);
            assertThat(net.controller().load("Extra").executed()).isTrue();
            assertThat(bridge.sensorsFed()).isEqualTo(fed + 1);
            bridge.run(1);
            assertThat(net.controller().value(extra).tick()).as("the reloaded instance is fed")
                    .isEqualTo(bridge.lastSnapshot().tick());
        }
    }

    @Test
    void shouldSendEveryChangedValueInRealTimeDroppingNoneInBetween() throws Exception {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.REAL_TIME);
             RuntimeNetwork net = RuntimeNetwork.start(NetworkRepository.load(NETWORK),
                     RuntimeOptions.defaults())) {
            java.util.concurrent.atomic.AtomicLong changes = new java.util.concurrent.atomic.AtomicLong();
            Value[] last = new Value[1];
            long changed;
            long sent;
            // Module Legs (inverse kinematics) is the one writer of the targets: held, nothing changes them, so the
            // window's two edges are counted with nothing in flight.
            assertThat(net.controller().hold("Legs").executed()).isTrue();
            try (AutoCloseable watch = net.controller().observe(TARGETS, (ref, id, v) -> {
                if (!v.samePayload(last[0])) {
                    changes.incrementAndGet();
                    last[0] = v;
                }
            }); SimBridge bridge = SimBridge.realTime(net, sim)) {
                Thread.sleep(200);
                long changesBefore = changes.get();
                long sentBefore = bridge.commandsSent();
                assertThat(net.controller().resume("Legs").executed()).isTrue();
                Thread.sleep(2000);
                assertThat(net.controller().hold("Legs").executed()).isTrue();
                Thread.sleep(200); // a firing under way when Legs was held commits, and the bridge sends it
                changed = changes.get() - changesBefore;
                sent = bridge.commandsSent() - sentBefore;
            }
            assertThat(changed).as("the gait changes the targets every 10 ms").isGreaterThan(50);
            assertThat(sent).as("commands sent, one per changed value").isEqualTo(changed);
        }
    }

    @Test
    void shouldSendEveryChangedTargetStampedWithItsSourceTickAndFollowTargetsReplacedLive() throws Exception {
        Course pushed = Course.flat().withStimuli(List.of(new Push(0.6, 0.1, 200, 225)));
        try (RoqSimulator sim = RoqSimulator.open(pushed, SimMode.STEPPED);
             RuntimeNetwork net = start();
             SimBridge bridge = SimBridge.stepped(net, sim, 0, 1)) {
            List<Value> written = new ArrayList<>();
            try (AutoCloseable watch = net.controller().observe(TARGETS, (ref, id, v) -> written.add(v))) {
                bridge.run(1);
                int changedCycles = 0;
                Value lastOfCycle = net.controller().value(TARGETS);
                long sentBefore = bridge.commandsSent();
                long[] applied = new long[64];
                long[] source = new long[64];
                long seen = sim.appliedCommands(0, applied, source);
                long stamped = 0;
                long newest = 0;
                long worst = 0;
                for (int t = 1; t < 1200; t++) {
                    bridge.run(1);
                    Value newestWritten = written.isEmpty() ? null : written.get(written.size() - 1);
                    if (newestWritten != null && !newestWritten.samePayload(lastOfCycle)) {
                        changedCycles++;
                        lastOfCycle = newestWritten;
                    }
                    long count = sim.appliedCommands(seen, applied, source);
                    for (int i = 0; i < count - seen; i++) {
                        if (source[i] > newest) { // the first command computed from a newer snapshot
                            stamped++;
                            newest = source[i];
                            worst = Math.max(worst, applied[i] - source[i]);
                        }
                    }
                    seen = count;
                }
                assertThat(bridge.commandsSent() - sentBefore).as("stepped: one command per cycle whose targets changed")
                        .isEqualTo(changedCycles);
                assertThat(stamped).as("commands computed from a snapshot (the reflex's)").isPositive();
                assertThat(worst).as("ticks from a snapshot to the tick the loop applied the first command computed from it").isLessThanOrEqualTo(1);
            }

            long sent = bridge.commandsSent();
            assertThat(net.controller().apply("delete", NetworkEdits.deleteNode(TARGETS)).executed()).isTrue();
            bridge.run(100);
            assertThat(bridge.commandsSent()).as("deleted targets are dropped at once").isEqualTo(sent);
            assertThat(net.controller().apply("add", NetworkEdits.all(
                    NetworkEdits.addNode("main", NodeInfo.data("joint targets", JointTargets.class.getName())),
                    NetworkEdits.addConnection("Legs", ConnectionInfo.writer(IK, TARGETS)))).executed()).isTrue();
            bridge.run(100);
            assertThat(bridge.commandsSent()).as("targets added live are followed").isGreaterThan(sent);
        }
    }
}
