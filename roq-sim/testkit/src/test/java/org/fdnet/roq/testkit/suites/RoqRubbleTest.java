package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.FragileCell;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.DrivenClock;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * networks/roq-rubble.fdn on the simulated RoQ, stepped: flat ground with and without a fragile cell, and the
 * {@code crossing} course (rubble with bands of fragile cells in the feet's lanes).
 */
@Timeout(120)
class RoqRubbleTest {
    private static final Path RUBBLE = Path.of("..", "networks", "roq-rubble.fdn");

    /**
     * What a run saw, counted each 10 ms.
     *
     * @param brokenWhileLoaded  ground truth ({@link CourseMeter}): cells broken other than under a pressing probe
     * @param cellsFoundByProbe  cells that broke under a pressing probe whose foothold the probe then rejected
     * @param cellsRetried       shorter steps the same leg probed next after such a rejection
     * @param cellsAvoided       of those, the ones where that shorter step was accepted
     */
    record Run(double distance, boolean fallen, int rejected, int accepted, int broken, int brokenWhileLoaded,
               long fragileFound, long fragileAvoided, int cellsFoundByProbe, int cellsRetried, int cellsAvoided) {
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
            CourseMeter meter = new CourseMeter(bridge.lastSnapshot(), course.fragileCells());
            long lastAttempt = 0;
            int rejected = 0;
            int accepted = 0;
            boolean fallen = false;
            long brokeDuringAttempt = -1;
            int foundLeg = -1;
            int cellsFoundByProbe = 0;
            int cellsRetried = 0;
            int cellsAvoided = 0;
            for (int t = 0; t < seconds * 100; t++) {
                bridge.run(10);
                Value verdict = value(net, "probe verdict", "Probing");
                if (verdict != null && verdict.length() == 3 && (long) verdict.element(2) != lastAttempt
                        && verdict.element(2) > 0) {
                    lastAttempt = (long) verdict.element(2);
                    int leg = (int) verdict.element(0);
                    if (leg == foundLeg) {
                        cellsRetried++;
                    }
                    if (verdict.element(1) < 0) {
                        rejected++;
                        if (lastAttempt == brokeDuringAttempt) {
                            cellsFoundByProbe++;
                            foundLeg = leg;
                        } else if (leg != foundLeg) {
                            foundLeg = -1;
                        }
                    } else {
                        accepted++;
                        if (leg == foundLeg) {
                            cellsAvoided++;
                        }
                        foundLeg = -1;
                    }
                }
                int probeBroken = meter.probeBroken();
                meter.sample(bridge.lastSnapshot(), net);
                if (meter.probeBroken() > probeBroken) {
                    brokeDuringAttempt = (long) value(net, "gait phase", "main").element(2); // under the pressing foot
                }
                fallen |= value(net, "fallen", "main").asBoolean();
            }
            return new Run(bridge.lastSnapshot().groundTruthBodyPosition(0) - x0, fallen, rejected, accepted,
                    meter.probeBroken() + meter.loadedBreakthroughs(), meter.loadedBreakthroughs(), count(net, "fragile found"), count(net, "fragile avoided"), cellsFoundByProbe,
                    cellsRetried, cellsAvoided);
        }
    }

    /** A Probing counter, -1 when module Probing is not loaded. */
    private static long count(RuntimeNetwork net, String node) {
        Value v = value(net, node, "Probing");
        return v == null ? -1 : Math.round(v.asDouble());
    }

    private static Value value(RuntimeNetwork net, String node, String module) {
        try {
            return net.controller().value(NodeRef.parse(node, module));
        } catch (RuntimeException notLoaded) {
            return null;
        }
    }

    /**
     * Flat ground with a fragile cell (40 N) right where the first swung foot, front-right (roq-rubble's crawl settles,
     * then starts with it), comes down: half its stride (0.3 m) ahead of where it stands, 0.30 m right of the centre line (its stance).
     */
    private static Course cellUnderTheFirstFoothold() {
        double[] foot = new double[3];
        RoqGeometry.footInBody(1, RoqGeometry.STANDING_POSE[0], RoqGeometry.STANDING_POSE[1],
                RoqGeometry.STANDING_POSE[2], foot);
        Course flat = Course.flat();
        double stride = 0.3;
        double stance = 0.30;
        return flat.withFragileCells(List.of(new FragileCell(flat.startX() + foot[0] + stride / 2,
                flat.startY() - stance, 0.24, 0.24, 0.03, 40)));
    }

    @Test
    void shouldFindAndAvoidAFragileCellOnTheCrossingWithoutFalling() throws Exception {
        Run r = run("crossing", 100);
        assertThat(r.fallen()).as("fallen").isFalse();
        // how far it walks is RoqCoursesTest's, across seeds and with noise, with margin below the measured median
        assertThat(r.fragileFound()).as("footholds that gave way under the probe (Probing/fragile found)")
                .isGreaterThanOrEqualTo(1);
        assertThat(r.fragileAvoided()).as("of them, avoided by a shorter step that held (Probing/fragile avoided)")
                .isGreaterThanOrEqualTo(1);
        assertThat(r.cellsFoundByProbe()).as("cells that broke under a probe which then rejected the foothold ("
                + r.broken() + " broken, " + r.brokenWhileLoaded() + " of them under a loaded foot)")
                .isGreaterThanOrEqualTo(1);
        // whether that shorter step holds is the ground's: on this run (module Posture levelling the body) the one
        // cell found was followed by two shorter steps onto its pit's edge, both rejected, and the gait stepped on
        // the third (docs/roq-networks.md, session 6); the network's own count above saw others avoided
        assertThat(r.cellsRetried()).as("of those, replaced by the same leg's next, shorter step (" + r.cellsAvoided()
                + " of them accepted)").isGreaterThanOrEqualTo(1);
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
        Run r = run("crossing", 60, "Probing");
        assertThat(r.rejected()).isZero();
        assertThat(r.brokenWhileLoaded()).as("cells broken under a loaded foot").isGreaterThanOrEqualTo(1);
    }
}
