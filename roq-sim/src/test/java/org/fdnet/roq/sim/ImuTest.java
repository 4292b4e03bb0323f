package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The IMU: MuJoCo's gyro and accelerometer on the body, with seeded noise and bias when sensor noise is on. */
class ImuTest {
    @Test
    void shouldReadGravityAndNoRotationStandingStill() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(1000);
            sim.read(s);
            assertThat(s.accelerometer(2)).as("specific force up: gravity").isCloseTo(9.81, offset(0.2));
            assertThat(s.accelerometer(0)).isCloseTo(0, offset(0.2));
            assertThat(s.accelerometer(1)).isCloseTo(0, offset(0.2));
            for (int i = 0; i < 3; i++) {
                assertThat(s.gyro(i)).as("gyro axis %d", i).isCloseTo(0, offset(0.01));
            }
        }
    }

    @Test
    void shouldSenseASidewaysPushAsAccelerationAndRollRate() {
        Course pushed = Course.flat().withStimuli(List.of(new Push(0.5, 0.2, 150, 90)));
        try (RoqSimulator sim = RoqSimulator.open(pushed, SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(500);
            double peakAccelY = 0;
            double peakRollRate = 0;
            for (int t = 0; t < 200; t++) {
                sim.step(1);
                sim.read(s);
                peakAccelY = Math.max(peakAccelY, s.accelerometer(1));
                peakRollRate = Math.max(peakRollRate, Math.abs(s.gyro(0)));
            }
            assertThat(peakAccelY).as("pushed to the left: specific force +y").isGreaterThan(1.0);
            assertThat(peakRollRate).as("the body rolls under the push").isGreaterThan(0.02);
        }
    }

    @Test
    void shouldAddTheSameBiasAndNoiseForTheSameSeed() {
        double[] a = meanGyro(SimOptions.of(SimMode.STEPPED).withNoise(7));
        double[] b = meanGyro(SimOptions.of(SimMode.STEPPED).withNoise(7));
        double[] clean = meanGyro(SimOptions.of(SimMode.STEPPED));
        assertThat(a).containsExactly(b);
        double largestBias = 0;
        for (int i = 0; i < 3; i++) {
            largestBias = Math.max(largestBias, Math.abs(a[i] - clean[i]));
            assertThat(Math.abs(a[i] - clean[i])).as("bias of axis %d within its ±10 mrad/s", i).isLessThan(0.0105);
        }
        assertThat(largestBias).as("a bias the averaging does not remove").isGreaterThan(0.001);
    }

    private static double[] meanGyro(SimOptions options) {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), options)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.step(500);
            double[] mean = new double[3];
            for (int t = 0; t < 500; t++) {
                sim.step(1);
                sim.read(s);
                for (int i = 0; i < 3; i++) {
                    mean[i] += s.gyro(i) / 500;
                }
            }
            return mean;
        }
    }
}
