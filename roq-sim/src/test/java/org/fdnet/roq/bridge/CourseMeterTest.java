package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

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

/** The course's figures the demo and the course suite report: breaks of each kind, track and heading errors. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class CourseMeterTest {

    @Test
    void shouldCountABreakDuringAProbesPressApartFromOneUnderALoadedFoot() {
        CourseMeter m = new CourseMeter(0, 0, 0);
        m.sample(0, 0, 0, false);
        m.sample(0, 0, 1, true);
        m.sample(0, 0, 1, false);
        m.sample(0, 0, 3, false);
        m.sample(0, 0, 4, true);
        assertThat(m.probeBroken()).isEqualTo(2);
        assertThat(m.loadedBreakthroughs()).isEqualTo(2);
    }

    @Test
    void shouldAverageTheTrackAndHeadingOverACrawlCycleSoTheSwayDoesNotCount() {
        CourseMeter m = new CourseMeter(1.0, 0.5, 0);
        for (int i = 0; i < 3 * CourseMeter.WINDOW; i++) {
            double sway = i % 2 == 0 ? 0.15 : -0.15; // sways ±0.15 m and ±0.1 rad about a line 0.2 m and 0.05 rad off
            m.sample(1.2 + sway, 0.55 + sway * 2 / 3, 0, false);
        }
        assertThat(m.endTrack()).isCloseTo(0.2, within(1e-9));
        assertThat(m.maxTrackError()).isCloseTo(0.2, within(1e-9));
        assertThat(m.endHeading()).isCloseTo(0.05, within(1e-9));
        for (int i = 0; i < CourseMeter.WINDOW; i++) {
            m.sample(1.0, 0.5, 0, false);
        }
        assertThat(m.endTrack()).as("back on the line").isCloseTo(0, within(1e-9));
        assertThat(m.maxTrackError()).as("the largest stays").isCloseTo(0.2, within(1e-9));
        assertThat(m.maxHeadingError()).isCloseTo(0.05, within(1e-9));
    }

    @Test
    void shouldWrapTheHeadingAcrossPi() {
        CourseMeter m = new CourseMeter(0, Math.PI - 0.01, 0);
        m.sample(0, -Math.PI + 0.01, 0, false);
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
