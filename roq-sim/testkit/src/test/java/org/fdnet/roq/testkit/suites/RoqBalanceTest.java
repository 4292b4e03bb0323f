package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.runtime.engine.DrivenClock;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * What module Balance does and does not do for RoQ (docs/roq-networks.md, "Balance"): the crawl is statically
 * stable enough that RoQ stays up without it — even at the crawl's fastest, duty factor 3/4 — because when the
 * centre of mass leaves the support triangle the body tips onto the lifted foot, which is at most
 * {@code clearance} (6 cm) above the ground. Pinned here so that a gait which does need Balance shows up.
 */
@Timeout(120)
class RoqBalanceTest {
    private static final Path WALK = Path.of("..", "networks", "roq-walk.fdn");
    private static final NodeRef CRAWL = NodeRef.parse("crawl", "Gait");
    /** The tilt of tipping onto a foot 6 cm up, about the diagonal 0.3 m from it (0.43 m on RoQ's stance): 0.2 rad. */
    private static final double TIP_ONTO_SWING_FOOT = Math.atan(0.06 / 0.3);

    /** roq-walk with its crawl at the fastest the gait allows: cycle 2 s, each leg 1/4 of it in the air. */
    private static NetworkInfo fastestCrawl(double swing) throws Exception {
        NetworkInfo info = NetworkRepository.load(WALK);
        List<Parameter> params = new ArrayList<>();
        for (Parameter p : info.node(CRAWL).parameters()) {
            if (!p.name().equals("cycle")) {
                params.add(p);
            }
        }
        params.add(new Parameter("cycle", ParameterType.DOUBLE, "2.0"));
        params.add(new Parameter("swing", ParameterType.DOUBLE, Double.toString(swing)));
        params.add(new Parameter("shift", ParameterType.DOUBLE, "0"));
        info.setParameters(CRAWL, params);
        return info;
    }

    @Test
    void shouldStayUpWithModuleBalanceUnloadedEvenOnTheFastestCrawlSinceTheLiftedFootCatchesTheTip()
            throws Exception {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED);
             RuntimeNetwork net = RuntimeNetwork.start(fastestCrawl(0.25),
                     RuntimeOptions.defaults().drivenClock(new DrivenClock(0)))) {
            SimBridge bridge = SimBridge.stepped(net, sim, 0, 1);
            bridge.run(1);
            assertThat(net.controller().unload("Balance").executed()).isTrue();
            double x0 = bridge.lastSnapshot().groundTruthBodyPosition(0);
            double tilt = 0;
            double lowest = Double.MAX_VALUE;
            for (int i = 0; i < 200; i++) {
                bridge.run(100);
                SensorSnapshot s = bridge.lastSnapshot();
                tilt = Math.max(tilt, Math.max(Math.abs(s.roll()), Math.abs(s.pitch())));
                lowest = Math.min(lowest, s.groundTruthBodyPosition(2));
            }
            assertThat(net.controller().value(NodeRef.parse("fallen", "main")).asBoolean()).isFalse();
            assertThat(tilt).as("largest roll or pitch, rad").isLessThan(TIP_ONTO_SWING_FOOT);
            assertThat(lowest).as("lowest body centre, m (0.27 standing; the body box's underside 5 cm below)")
                    .isGreaterThan(0.2);
            assertThat(bridge.lastSnapshot().groundTruthBodyPosition(0) - x0).as("metres walked in 20 s")
                    .isGreaterThan(1.0);
        }
    }

    @Test
    void shouldRefuseASwingThatWouldPutTwoLegsInTheAirAtOnce() {
        assertThatThrownBy(() -> RuntimeNetwork.start(fastestCrawl(0.3),
                RuntimeOptions.defaults().drivenClock(new DrivenClock(0))).close())
                .hasStackTraceContaining("swing")
                .hasStackTraceContaining("one leg in the air at a time");
    }
}
