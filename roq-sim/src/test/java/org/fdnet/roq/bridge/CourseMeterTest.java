package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The course's figures the demo and the course suite report: track and heading errors, a probe's press (the breaks: BreakthroughCausesTest). */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class CourseMeterTest {

    @Test
    void shouldAverageTheTrackAndHeadingOverACrawlCycleSoTheSwayDoesNotCount() {
        CourseMeter m = new CourseMeter(1.0, 0.5, List.of());
        for (int i = 0; i < 3 * CourseMeter.WINDOW; i++) {
            double sway = i % 2 == 0 ? 0.15 : -0.15; // sways ±0.15 m and ±0.1 rad about a line 0.2 m and 0.05 rad off
            m.sample(1.2 + sway, 0.55 + sway * 2 / 3);
        }
        assertThat(m.endTrack()).isCloseTo(0.2, within(1e-9));
        assertThat(m.maxTrackError()).isCloseTo(0.2, within(1e-9));
        assertThat(m.endHeading()).isCloseTo(0.05, within(1e-9));
        for (int i = 0; i < CourseMeter.WINDOW; i++) {
            m.sample(1.0, 0.5);
        }
        assertThat(m.endTrack()).as("back on the line").isCloseTo(0, within(1e-9));
        assertThat(m.maxTrackError()).as("the largest stays").isCloseTo(0.2, within(1e-9));
        assertThat(m.maxHeadingError()).isCloseTo(0.05, within(1e-9));
    }

    @Test
    void shouldWrapTheHeadingAcrossPi() {
        CourseMeter m = new CourseMeter(0, Math.PI - 0.01, List.of());
        m.sample(0, -Math.PI + 0.01);
        assertThat(m.endHeading()).isCloseTo(0.02, within(1e-9));
    }

    @Test
    void shouldTellAProbesPressFromTheNetworksGaitPhase() throws Exception {
        NetworkInfo n = new NetworkInfo("phase");
        n.addNode("main", NodeInfo.data("gait phase", "org.fdnet.runtime.library.DoublesData",
                new Parameter("length", ParameterType.LONG, "3")));
        try (RuntimeNetwork net = RuntimeNetwork.start(n, RuntimeOptions.defaults())) {
            NodeRef phase = new NodeRef("main", "gait phase");
            net.controller().setValue(phase, Value.ofDoubles(2, 0, 1));
            assertThat(CourseMeter.probing(net)).as("leg 2 probing").isTrue();
            net.controller().setValue(phase, Value.ofDoubles(2, 1, 0));
            assertThat(CourseMeter.probing(net)).as("leg 2 swinging, no probe").isFalse();
        }
        try (RuntimeNetwork none = RuntimeNetwork.start(new NetworkInfo("none"), RuntimeOptions.defaults())) {
            assertThat(CourseMeter.probing(none)).as("no gait phase: no press known").isFalse();
        }
    }
}
