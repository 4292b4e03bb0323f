package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.CourseLoader;
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
        try (RoqSimulator sim = RoqSimulator.open(CourseLoader.resolve(course), SimMode.STEPPED);
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
                    System.out.printf("t=%.2f broken %d probing=%s phase=%s%n", bridge.lastSnapshot().simTime(),
                            nowBroken, probing, phase);
                    broken = nowBroken;
                }
                fallen |= value(net, "fallen", "main").asBoolean();
                if (t % 500 == 0) {
                    System.out.printf("t=%.1f x=%.3f z=%.3f rej=%d acc=%d broken=%d fallen=%s%n",
                            bridge.lastSnapshot().simTime(), bridge.lastSnapshot().groundTruthBodyPosition(0) - x0,
                            bridge.lastSnapshot().groundTruthBodyPosition(2), rejected, accepted, broken, fallen);
                }
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

    @Test
    void shouldCrossTheFragileCourseProbingAndAvoidingItsFragileCells() throws Exception {
        Run r = run("fragile", 120);
        System.out.println(r);
        assertThat(r.fallen()).isFalse();
        assertThat(r.rejected()).as("footholds rejected by probing").isGreaterThanOrEqualTo(1);
        assertThat(r.brokenWhileLoaded()).as("cells broken under a loaded foot").isZero();
        assertThat(r.distance()).as("metres crossed").isGreaterThanOrEqualTo(2.0);
    }
}
