package org.fdnet.roq.testkit.suites;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.testkit.SimulatedRoq;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * What module Balance does and does not do for RoQ (docs/explanation/roq-control.md, "Balance"): the crawl is statically
 * stable enough that RoQ stays up without it — even at the crawl's fastest, duty factor 3/4 — because when the
 * centre of mass leaves the support triangle the body tips onto the lifted foot, which is at most
 * {@code clearance} (6 cm) above the ground. Pinned here so that a gait which does need Balance shows up. Flat ground,
 * sensor noise off.
 */
@Timeout(120)
class RoqBalanceTest {
    private static final Path WALK = Path.of("../../networks/roq-walk.fdn");
    private static final NodeRef CRAWL = NodeRef.parse("crawl", "Gait");
    /** The tilt of tipping onto a foot 6 cm up, about the diagonal 0.3 m from it (0.43 m on RoQ's stance): 0.2 rad. */
    private static final double TIP_ONTO_SWING_FOOT = Math.atan(0.06 / 0.3);

    /** roq-walk with its crawl at the fastest the gait allows: cycle 2 s, each leg 1/4 of it in the air. */
    private static NetworkInfo fastestCrawl(double swing) throws Exception {
        return crawl(swing, 0);
    }

    private static NetworkInfo crawl(double swing, double shift) throws Exception {
        NetworkInfo info = NetworkRepository.load(WALK);
        List<Parameter> params = new ArrayList<>();
        for (Parameter p : info.node(CRAWL).parameters()) {
            if (!p.name().equals("cycle")) {
                params.add(p);
            }
        }
        params.add(new Parameter("cycle", ParameterType.DOUBLE, "2.0"));
        params.add(new Parameter("swing", ParameterType.DOUBLE, Double.toString(swing)));
        params.add(new Parameter("shift", ParameterType.DOUBLE, Double.toString(shift)));
        info.setParameters(CRAWL, params);
        return info;
    }

    @Test
    void shouldStayUpWithModuleBalanceUnloadedEvenOnTheFastestCrawlSinceTheLiftedFootCatchesTheTip()
            throws Exception {
        try (SimulatedRoq roq = SimulatedRoq.builder().network(fastestCrawl(0.25)).course("flat").withoutNoise()
                .start()) {
            roq.unload("Balance");
            double tilt = 0;
            double lowest = Double.MAX_VALUE;
            for (int i = 0; i < 200; i++) { // 20 s, sampled every 0.1 s
                roq.advance(Duration.ofMillis(100));
                SensorSnapshot s = roq.snapshot();
                tilt = Math.max(tilt, Math.max(Math.abs(s.roll()), Math.abs(s.pitch())));
                lowest = Math.min(lowest, s.groundTruthBodyPosition(2));
            }

            roq.assertThat().noFall().walkedAtLeast(1.0);
            assertThat(tilt).as("largest roll or pitch, rad").isLessThan(TIP_ONTO_SWING_FOOT);
            assertThat(lowest).as("lowest body centre, m (0.27 standing; the body box's underside 5 cm below)")
                    .isGreaterThan(0.2);
        }
    }

    @Test
    void shouldRefuseASwingThatWouldPutTwoLegsInTheAirAtOnce() {
        assertThatThrownBy(() -> SimulatedRoq.builder().network(fastestCrawl(0.3)).start().close())
                .hasStackTraceContaining("module 'Gait', node 'crawl': parameter 'swing' must be a number in"
                        + " [0.05, 0.25] cycle, was 0.3");
        assertThatThrownBy(() -> SimulatedRoq.builder().network(crawl(0.2, 0.1)).start().close())
                .hasStackTraceContaining("module 'Gait', node 'crawl': parameters 'shift' (0.1) and 'swing' (0.2) do"
                        + " not fit together: swing + shift must be at most 0.25 of the cycle (one leg in the air at a"
                        + " time)");
    }
}
