package org.fdnet.logger.store;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class DoubleTextTest {
    private static String text(double v) {
        byte[] buf = new byte[32];
        return new String(buf, 0, DoubleText.write(v, buf, 0), StandardCharsets.US_ASCII);
    }

    @Test
    void shouldWriteShortNumbersAsJavaPrintsThem() {
        double[] values = {0.25, 3.0, -3.0, 1234.567, 0.001, 9999999.0, 0.1 + 0.2, 1.0E7, 1.0E-4, -0.0, 0.0,
                Double.NaN, Double.NEGATIVE_INFINITY, Double.MIN_VALUE, Double.MAX_VALUE, 123456.75, 0.007};
        for (double v : values) {
            assertThat(text(v)).as("%s", v).isEqualTo(Double.toString(v));
        }
    }

    @Test
    void shouldAlwaysReadBackAsExactlyTheSameDouble() {
        SplittableRandom random = new SplittableRandom(21);
        for (int i = 0; i < 200_000; i++) {
            // decimals of every length, products like a sensor's, and arbitrary bit patterns
            double v = switch (i % 3) {
                case 0 -> Math.round(random.nextDouble(-1e7, 1e7) * Math.pow(10, i % 9)) / Math.pow(10, i % 9);
                case 1 -> i * 0.001 * (random.nextBoolean() ? 1 : -1);
                default -> Double.longBitsToDouble(random.nextLong());
            };
            String t = text(v);
            assertThat(Double.doubleToLongBits(Double.parseDouble(t))).as(t).isEqualTo(Double.doubleToLongBits(v));
            assertThat(t.length()).as("%s no longer than Java's %s", t, Double.toString(v))
                    .isLessThanOrEqualTo(Double.toString(v).length());
        }
    }
}
