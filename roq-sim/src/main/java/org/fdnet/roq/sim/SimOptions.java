package org.fdnet.roq.sim;

/**
 * How to open a {@link RoqSimulator}.
 *
 * @param mode          real-time thread or stepped
 * @param priority      SCHED_FIFO priority of the real-time thread (1..99)
 * @param sensorNoise   whether sensors get seeded noise (joint angles ±0.5 mrad, forces ±0.5 N, ranges ±5 mm)
 * @param noiseSeed     the noise's seed (same seed, same noise)
 * @param dropHeight    how far above its standing height the robot is set down, m (0 = feet on the ground)
 * @param rangeSensors  whether the infrared, ultrasonic and depth-image rays are cast (they are the dearest part of
 *                      a tick); without them those readings are NaN
 */
public record SimOptions(SimMode mode, int priority, boolean sensorNoise, long noiseSeed, double dropHeight,
                         boolean rangeSensors) {
    /** The SCHED_FIFO priority used unless told otherwise (DESIGN.md: the measured configuration). */
    public static final int DEFAULT_PRIORITY = 80;

    /** Checks the figures. */
    public SimOptions {
        if (mode == null) {
            throw new IllegalArgumentException("mode must be given");
        }
        if (priority < 1 || priority > 99) {
            throw new IllegalArgumentException("priority must be 1..99, was " + priority);
        }
        if (!(dropHeight >= 0 && dropHeight <= 2)) {
            throw new IllegalArgumentException("dropHeight must be 0..2 m, was " + dropHeight);
        }
    }

    /** Options with every sensor on. */
    public SimOptions(SimMode mode, int priority, boolean sensorNoise, long noiseSeed, double dropHeight) {
        this(mode, priority, sensorNoise, noiseSeed, dropHeight, true);
    }

    /** {@code mode}, priority 80, no noise, feet on the ground, every sensor on. */
    public static SimOptions of(SimMode mode) {
        return new SimOptions(mode, DEFAULT_PRIORITY, false, 0, 0, true);
    }

    /** These options with the range sensors (infrared, ultrasonic, depth image) on or off. */
    public SimOptions withRangeSensors(boolean on) {
        return new SimOptions(mode, priority, sensorNoise, noiseSeed, dropHeight, on);
    }

    /** These options with seeded sensor noise. */
    public SimOptions withNoise(long seed) {
        return new SimOptions(mode, priority, true, seed, dropHeight, rangeSensors);
    }

    /** These options with the robot set down {@code metres} above its standing height. */
    public SimOptions withDropHeight(double metres) {
        return new SimOptions(mode, priority, sensorNoise, noiseSeed, metres, rangeSensors);
    }

    /** These options with another SCHED_FIFO priority. */
    public SimOptions withPriority(int p) {
        return new SimOptions(mode, p, sensorNoise, noiseSeed, dropHeight, rangeSensors);
    }
}
