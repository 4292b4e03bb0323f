package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

/** A closed simulator refuses native calls with a clear message; its last snapshot stays readable; close twice is fine. */
class SimulatorLifecycleTest {
    @Test
    void shouldRefuseNativeCallsAfterCloseAndKeepTheLastSnapshot() {
        RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED);
        sim.step(25);
        sim.close();
        sim.close();
        SensorSnapshot s = new SensorSnapshot();
        assertThat(sim.read(s)).isEqualTo(25);
        assertThatThrownBy(() -> sim.step(1)).isInstanceOf(IllegalStateException.class)
                .hasMessage("roq-sim simulator of course flat is closed");
        assertThatThrownBy(() -> sim.step(-1)).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void shouldRefuseAStartOutsideTheCourse() {
        assertThatThrownBy(() -> Course.flat().withStart(5, 0)).isInstanceOf(IllegalArgumentException.class)
                .hasMessage("start 5.0 0.0 lies outside the course");
    }
}
