package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import org.junit.jupiter.api.Test;

/** The infrared, ultrasonic and depth rays see the ground where geometry puts it; switched off they read NaN. */
class RangeSensorTest {
    @Test
    void shouldSeeTheFlatGroundWhereTheGeometrySaysItIs() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(500);
            sim.read(s);
            double irHeight = s.groundTruthBodyPosition(2) + RoqGeometry.IR_POSITION[2];
            assertThat(s.irRange()).isCloseTo(irHeight / Math.sin(RoqGeometry.IR_PITCH_DOWN), offset(0.01));
            assertThat(s.ultrasonicRange()).as("nothing ahead on flat ground").isEqualTo(RoqGeometry.ULTRASONIC_MAX_RANGE);
            long frames = s.depthFrames();
            float bottom = s.depth(RoqGeometry.DEPTH_WIDTH / 2, RoqGeometry.DEPTH_HEIGHT - 1);
            float top = s.depth(RoqGeometry.DEPTH_WIDTH / 2, 0);
            assertThat(bottom).as("the lowest row looks at the nearest ground").isLessThan(top);
            double camHeight = s.groundTruthBodyPosition(2) + RoqGeometry.CAMERA_POSITION[2];
            double lowestPitch = RoqGeometry.CAMERA_PITCH_DOWN
                    + (RoqGeometry.DEPTH_HEIGHT - 0.5) / RoqGeometry.DEPTH_HEIGHT * RoqGeometry.CAMERA_FOV_Y - RoqGeometry.CAMERA_FOV_Y / 2;
            assertThat((double) bottom).isCloseTo(camHeight / Math.sin(lowestPitch), offset(0.01));
            sim.step(RoqGeometry.DEPTH_ROW_PERIOD_TICKS * RoqGeometry.DEPTH_HEIGHT * 2);
            sim.read(s);
            assertThat(s.depthFrames()).isEqualTo(frames + 2);
        }
    }

    @Test
    void shouldCastTheSameRaysAtTheGroundAsMuJoCo() throws Exception {
        Course course = CourseLoader.resolve("fragile").withFragileCells(java.util.List.of(
                new FragileCell(0.3, 0.2, 0.3, 0.3, 0.04, 500)));
        try (RoqSimulator sim = RoqSimulator.open(course, SimMode.STEPPED)) {
            java.util.SplittableRandom random = new java.util.SplittableRandom(11);
            int hits = 0;
            for (int i = 0; i < 400; i++) {
                double x = random.nextDouble(-1.9, 1.9);
                double y = random.nextDouble(-0.9, 0.9);
                double z = random.nextDouble(0.05, 0.6);
                double pitch = random.nextDouble(-0.2, 1.5);
                double yaw = random.nextDouble(-Math.PI, Math.PI);
                String ray = x + " " + y + " " + z + " " + Math.cos(pitch) * Math.cos(yaw) + " "
                        + Math.cos(pitch) * Math.sin(yaw) + " " + -Math.sin(pitch);
                double ours = sim.modelValue(11, ray);
                double mujoco = sim.modelValue(12, ray);
                double hx = x + mujoco * Math.cos(pitch) * Math.cos(yaw);
                double hy = y + mujoco * Math.cos(pitch) * Math.sin(yaw);
                if (mujoco > 0 && (Math.abs(hx) > 2 - 1e-6 || Math.abs(hy) > 1 - 1e-6)) {
                    continue; // MuJoCo's heightfield has side walls up to its full elevation; ours only below the surface
                }
                assertThat(ours).as("ray %s", ray).isCloseTo(mujoco, offset(1e-6));
                if (mujoco > 0) {
                    hits++;
                }
            }
            assertThat(hits).as("most rays hit the ground").isGreaterThan(250);
        }
    }

    @Test
    void shouldReadNaNWithTheRangeSensorsOff() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimOptions.of(SimMode.STEPPED).withRangeSensors(false))) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(300);
            sim.read(s);
            assertThat(s.irRange()).isNaN();
            assertThat(s.ultrasonicRange()).isNaN();
            assertThat(s.depth(3, 3)).isNaN();
            assertThat(s.depthFrames()).isZero();
            assertThat(s.footContact(0)).as("the rest still senses").isTrue();
        }
    }
}
