package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/**
 * The servo follows a step of its target within its rise time, tested on a leg in free fall (the robot set down
 * 1.5 m up: no ground, no weight on the leg for 0.5 s).
 */
class ServoTest {
    /** Step size, rad, and the rise time the servo must meet for it (docs/explanation/roq-sim.md: PD, motor limits, armature). */
    static final double STEP = 0.4;
    static final int RISE_TICKS = 150;

    @Test
    void shouldFollowAStepTargetWithinItsRiseTime() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimOptions.of(SimMode.STEPPED).withDropHeight(1.5))) {
            SensorSnapshot s = new SensorSnapshot();
            int knee = RoqGeometry.jointIndex(0, 2);
            sim.step(20);
            sim.read(s);
            double start = s.jointAngle(knee);
            JointCommand command = new JointCommand().target(knee, start - STEP);
            sim.send(command);
            double peakOvershoot = 0;
            int reached = -1;
            double peakSpeed = 0;
            for (int t = 1; t <= 300; t++) {
                sim.step(1);
                sim.read(s);
                double progress = (start - s.jointAngle(knee)) / STEP;
                if (reached < 0 && progress >= 0.9) {
                    reached = t;
                }
                peakOvershoot = Math.max(peakOvershoot, progress - 1);
                peakSpeed = Math.max(peakSpeed, Math.abs(s.jointVelocity(knee)));
                assertThat(Math.abs(s.jointTorque(knee))).isLessThanOrEqualTo(RoqGeometry.maxJointTorque() + 1e-9);
            }
            assertThat(reached).as("ticks to 90 %% of the step").isBetween(1, RISE_TICKS);
            assertThat(peakOvershoot).as("overshoot").isLessThan(0.25);
            assertThat(Math.abs(s.jointAngle(knee) - (start - STEP))).as("settled on the target").isLessThan(0.02);
            assertThat(peakSpeed).as("the motor's no-load speed bounds the joint").isLessThanOrEqualTo(RoqGeometry.noLoadJointSpeed() * 1.05);
            assertThat(s.footContact(0)).as("still in the air").isFalse();
        }
    }
}
