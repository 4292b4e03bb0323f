package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.offset;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A broken cell leaves the model at the one safe point, between two steps: a break stimulus before the step of
 * its own tick; a break under load (decided after that tick's step) before the next tick's step.
 */
class ModelEditTest {
    private static final double HEIGHT = 0.03;
    private static final double DROP = HEIGHT + 0.02;

    @Test
    void shouldDropACellBrokenByAStimulusBeforeTheStepOfItsTick() {
        Course course = Course.flat().withFragileCells(List.of(new FragileCell(1.0, 0.5, 0.2, 0.2, HEIGHT, 40)))
                .withStimuli(List.of(new CellBreak(0.05, 0)));
        try (RoqSimulator sim = RoqSimulator.open(course, SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(1);
            double standing = sim.modelValue(6, "fragile_0");
            do {
                assertThat(sim.modelValue(6, "fragile_0")).isEqualTo(standing);
                sim.step(1);
                sim.read(s);
            } while (!s.isCellBroken(0) && s.tick() < 200);
            assertThat(s.isCellBroken(0)).as("broken by the stimulus").isTrue();
            assertThat(sim.modelValue(6, "fragile_0")).as("dropped before this tick's mj_step1")
                    .isCloseTo(standing - DROP, offset(1e-12));
        }
    }

    @Test
    void shouldDropACellBrokenUnderLoadBeforeTheNextStep() {
        double[] foot = RoqGeometry.footInBody(0, RoqGeometry.STANDING_POSE[0], RoqGeometry.STANDING_POSE[1],
                RoqGeometry.STANDING_POSE[2], new double[3]);
        Course course = Course.flat().withFragileCells(List.of(new FragileCell(foot[0], foot[1], 0.16, 0.16, HEIGHT,
                FragileCellTest.STRENGTH)));
        try (RoqSimulator sim = RoqSimulator.open(course, SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(1000);
            sim.read(s); // a command is issued at the tick last read: fresh, not stale
            sim.send(new JointCommand()
                    .target(RoqGeometry.jointIndex(1, 1), RoqGeometry.STANDING_POSE[1] + 0.3)
                    .target(RoqGeometry.jointIndex(2, 1), RoqGeometry.STANDING_POSE[1] + 0.3));
            double before;
            do {
                before = sim.modelValue(6, "fragile_0");
                sim.step(1);
                sim.read(s);
            } while (!s.isCellBroken(0) && s.tick() < 3000);
            assertThat(s.isCellBroken(0)).as("breaks under the loaded foot").isTrue();
            assertThat(sim.modelValue(6, "fragile_0")).as("the edit waits for the safe point").isEqualTo(before);
            sim.step(1);
            assertThat(sim.modelValue(6, "fragile_0")).as("dropped before the next mj_step1")
                    .isCloseTo(before - DROP, offset(1e-12));
        }
    }
}
