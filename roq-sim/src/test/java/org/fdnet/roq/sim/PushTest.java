package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;

/** External pushes on the body and cell breaks: applied in the tick, from the API or from a course file. */
class PushTest {
    @Test
    void shouldMoveTheBodyInThePushDirection() {
        double[] left = displacementUnder(new Push(0.5, 0.3, 150, 90));
        assertThat(left[1]).as("pushed to the left: +y").isGreaterThan(0.005);
        assertThat(Math.abs(left[0])).as("little along x").isLessThan(left[1] / 3);
        double[] back = displacementUnder(new Push(0.5, 0.3, 150, 180));
        assertThat(back[0]).as("pushed backwards: -x").isLessThan(-0.005);
        assertThat(Math.abs(back[1])).as("little along y").isLessThan(-back[0] / 3);
    }

    @Test
    void shouldNotMoveTheBodyWithoutAPush() {
        double[] still = displacementUnder(null);
        assertThat(Math.hypot(still[0], still[1])).isLessThan(0.001);
    }

    @Test
    void shouldApplyAPushSetFromJavaWhileRunningAndReportItAsGroundTruth() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(300);
            sim.read(s);
            sim.stimulate(new Push(0.4, 0.05, 80, 0));
            sim.step(99);
            sim.read(s);
            assertThat(s.groundTruthPushForce(0)).as("before its start").isZero();
            sim.step(2);
            sim.read(s);
            assertThat(s.groundTruthPushForce(0)).as("acting").isCloseTo(80, org.assertj.core.data.Offset.offset(1e-9));
            sim.step(60);
            sim.read(s);
            assertThat(s.groundTruthPushForce(0)).as("over").isZero();
        }
    }

    @Test
    void shouldPushInRealTimeMode() throws InterruptedException {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.REAL_TIME)) {
            SensorSnapshot s = new SensorSnapshot();
            Thread.sleep(300);
            sim.read(s);
            double y0 = s.groundTruthBodyPosition(1);
            sim.stimulate(new Push(s.simTime() + 0.05, 0.3, 150, 90));
            Thread.sleep(800);
            sim.read(s);
            assertThat(s.groundTruthBodyPosition(1) - y0).isGreaterThan(0.005);
        }
    }

    @Test
    void shouldCarryPushesAndBreaksInACourseFile() throws CourseFormatException {
        double[] foot = RoqGeometry.footInBody(0, RoqGeometry.STANDING_POSE[0], RoqGeometry.STANDING_POSE[1],
                RoqGeometry.STANDING_POSE[2], new double[3]);
        Course c = CourseLoader.parse("pushed.course", String.format(java.util.Locale.ROOT, """
                terrain = flat
                fragile = %s %s 0.16 0.16 0.03 1000
                push    = 0.5 0.3 150 90
                break   = 1.2 0
                """, foot[0], foot[1]));
        assertThat(c.stimuli()).containsExactly(new Push(0.5, 0.3, 150, 90), new CellBreak(1.2, 0));
        try (RoqSimulator sim = RoqSimulator.open(c, SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(1190);
            sim.read(s);
            assertThat(s.groundTruthBodyPosition(1)).as("the course's push moved it left").isGreaterThan(0.005);
            assertThat(s.isCellBroken(0)).as("a 1000 N cell bears the robot").isFalse();
            double loaded = s.footForce(0);
            sim.step(30);
            sim.read(s);
            assertThat(s.isCellBroken(0)).as("breaks at its time").isTrue();
            assertThat(loaded).as("the foot was loaded").isGreaterThan(20);
            assertThat(s.footForce(0)).as("the sole's force dropped").isLessThan(loaded / 4);
        }
    }

    @Test
    void shouldRefuseBadValuesNamingTheParameter() {
        assertThatThrownBy(() -> new Push(-1, 0.1, 10, 0)).hasMessageContaining("push start");
        assertThatThrownBy(() -> new Push(0, 0, 10, 0)).hasMessageContaining("push duration");
        assertThatThrownBy(() -> new Push(0, 0.1, Double.NaN, 0)).hasMessageContaining("push force");
        assertThatThrownBy(() -> new Push(0, 0.1, 5000, 0)).hasMessageContaining("push force");
        assertThatThrownBy(() -> new Push(0, 0.1, 10, Double.POSITIVE_INFINITY)).hasMessageContaining("push direction");
        assertThatThrownBy(() -> new CellBreak(1, -2)).hasMessageContaining("break cell");
        assertThatThrownBy(() -> Course.flat().withStimuli(List.of(new CellBreak(1, 0))))
                .hasMessageContaining("break names fragile cell 0");
        assertThatThrownBy(() -> CourseLoader.parse("bad.course", "push = 1 0.1 -5 0\n"))
                .isInstanceOf(CourseFormatException.class).hasMessageContaining("bad.course:1: push force");
        assertThatThrownBy(() -> CourseLoader.parse("bad.course", "\nbreak = 1\n"))
                .hasMessageContaining("bad.course:2: expected break = time cell");
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED)) {
            assertThatThrownBy(() -> sim.stimulate(new CellBreak(0.1, 3))).hasMessageContaining("break cell 3");
        }
    }

    /** Body displacement (x, y) from 0.4 s to 1.5 s, under {@code push} (or none). */
    private static double[] displacementUnder(Push push) {
        Course c = push == null ? Course.flat() : Course.flat().withStimuli(List.of(push));
        try (RoqSimulator sim = RoqSimulator.open(c, SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(400);
            sim.read(s);
            double x0 = s.groundTruthBodyPosition(0);
            double y0 = s.groundTruthBodyPosition(1);
            sim.step(1100);
            sim.read(s);
            return new double[] {s.groundTruthBodyPosition(0) - x0, s.groundTruthBodyPosition(1) - y0};
        }
    }
}
