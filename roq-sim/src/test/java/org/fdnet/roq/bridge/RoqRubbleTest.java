package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import java.util.List;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.FragileCell;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.runtime.DrivenClock;
import org.fdnet.runtime.RuntimeNetwork;
import org.fdnet.runtime.RuntimeOptions;
import org.fdnet.runtime.Value;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** networks/roq-rubble.fdn on the simulated RoQ, stepped, on the fragile course (rubble with fragile cells). */
@Timeout(120)
class RoqRubbleTest {
    private static final Path RUBBLE = Path.of("..", "networks", "roq-rubble.fdn");

    /** What a run saw, counted each 10 ms. */
    record Run(double distance, boolean fallen, int rejected, int accepted, int broken, int brokenWhileLoaded) {
    }

    static Run run(String course, int seconds, String... unloaded) throws Exception {
        return run(CourseLoader.resolve(course), seconds, unloaded);
    }

    static Run run(Course course, int seconds, String... unloaded) throws Exception {
        try (RoqSimulator sim = RoqSimulator.open(course, SimMode.STEPPED);
             RuntimeNetwork net = RuntimeNetwork.start(NetworkRepository.load(RUBBLE),
                     RuntimeOptions.defaults().drivenClock(new DrivenClock(0)))) {
            for (String module : unloaded) {
                assertThat(net.controller().unload(module).executed()).as("unload " + module).isTrue();
            }
            SimBridge bridge = SimBridge.stepped(net, sim, 0, 1);
            bridge.run(1);
            double x0 = bridge.lastSnapshot().groundTruthBodyPosition(0);
            long lastAttempt = 0;
            int rejected = 0;
            int accepted = 0;
            int broken = 0;
            int brokenWhileLoaded = 0;
            boolean fallen = false;
            for (int t = 0; t < seconds * 100; t++) {
                bridge.run(10);
                Value verdict = value(net, "probe verdict", "Probing");
                if (verdict != null && verdict.length() == 3 && (long) verdict.element(2) != lastAttempt
                        && verdict.element(2) > 0) {
                    lastAttempt = (long) verdict.element(2);
                    if (verdict.element(1) < 0) {
                        rejected++;
                    } else {
                        accepted++;
                    }
                }
                int nowBroken = bridge.lastSnapshot().brokenCellCount();
                if (nowBroken > broken) {
                    Value phase = value(net, "gait phase", "main");
                    boolean probing = phase != null && phase.length() == 3 && phase.element(2) > 0;
                    if (!probing) {
                        brokenWhileLoaded += nowBroken - broken;
                    }
                    broken = nowBroken;
                }
                fallen |= value(net, "fallen", "main").asBoolean();
            }
            return new Run(bridge.lastSnapshot().groundTruthBodyPosition(0) - x0, fallen, rejected, accepted, broken,
                    brokenWhileLoaded);
        }
    }

    private static Value value(RuntimeNetwork net, String node, String module) {
        try {
            return net.controller().value(NodeRef.parse(node, module));
        } catch (RuntimeException notLoaded) {
            return null;
        }
    }

    /** Flat ground with a fragile cell (40 N) right where the first swung foot, hind-right, comes down. */
    private static Course cellUnderTheFirstFoothold() {
        double[] foot = new double[3];
        RoqGeometry.footInBody(3, RoqGeometry.STANDING_POSE[0], RoqGeometry.STANDING_POSE[1],
                RoqGeometry.STANDING_POSE[2], foot);
        Course flat = Course.flat();
        double stride = 0.15;
        return flat.withFragileCells(List.of(new FragileCell(flat.startX() + foot[0] + stride / 2,
                flat.startY() + foot[1], 0.24, 0.24, 0.03, 40)));
    }

    @Test
    void shouldAcceptEveryFootholdOnFlatGroundAndWalkOn() throws Exception {
        Run r = run(Course.flat(), 30);
        assertThat(r.rejected()).as("footholds rejected on solid flat ground").isZero();
        assertThat(r.accepted()).as("footholds probed and accepted in 30 s (each probe pauses the gait)").isGreaterThanOrEqualTo(10);
        assertThat(r.fallen()).isFalse();
        assertThat(r.distance()).as("metres walked").isGreaterThan(0.3);
    }

    @Test
    void shouldRejectAFootholdOnAFragileCellSoThatOnlyTheProbeBreaksIt() throws Exception {
        Run r = run(cellUnderTheFirstFoothold(), 20);
        assertThat(r.rejected()).as("footholds rejected by probing").isGreaterThanOrEqualTo(1);
        assertThat(r.broken()).as("the cell gave way under the probe").isEqualTo(1);
        assertThat(r.brokenWhileLoaded()).as("cells broken under a loaded foot").isZero();
        assertThat(r.fallen()).isFalse();
        assertThat(r.distance()).as("metres walked on").isGreaterThan(0.2);
    }

    @Test
    void shouldBreakTheCellUnderTheFirstFootholdWhenModuleProbingIsUnloaded() throws Exception {
        Run r = run(cellUnderTheFirstFoothold(), 20, "Probing");
        assertThat(r.rejected()).isZero();
        assertThat(r.brokenWhileLoaded()).as("cells broken under a loaded foot").isEqualTo(1);
    }

    @Test
    void shouldBreakThroughAFragileCellWhenModuleProbingIsUnloaded() throws Exception {
        Run r = run("fragile", 90, "Probing");
        assertThat(r.rejected()).isZero();
        assertThat(r.brokenWhileLoaded()).as("cells broken under a loaded foot").isGreaterThanOrEqualTo(1);
    }
}
