package org.fdnet.event.wire;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class AsciiNumberTest {
    private static double parseDouble(String s) {
        byte[] b = ("xx" + s + "yy").getBytes(StandardCharsets.UTF_8);
        return AsciiNumber.parseDouble(b, 2, b.length - 2);
    }

    private static double parseLong(String s) {
        byte[] b = ("x" + s).getBytes(StandardCharsets.UTF_8);
        return AsciiNumber.parseLong(b, 1, b.length);
    }

    @Test
    void shouldReadEveryDoubleBitForBitAsTheJdkDoes() {
        SplittableRandom random = new SplittableRandom(12);
        List<String> texts = new ArrayList<>(List.of("0", "-0", "-0.0", "1.", ".5", "+3.25", " 2.5 ", "\t7\n",
                "1e22", "1e23", "1e-22", "1e-23", "9007199254740991", "9007199254740993", "123456789012345678",
                "1234567890123456789012", "4.9E-324", "1.7976931348623157E308", "0.1", "0.30000000000000004",
                "NaN", "-Infinity", "1d", "0x1p3", "1E+5", "1e0005", "00000000000000000000012.5"));
        for (int i = 0; i < 20_000; i++) {
            texts.add(Double.toString(Double.longBitsToDouble(random.nextLong())));
            texts.add(Double.toString(random.nextDouble(-1000, 1000)));
            texts.add(Double.toString(random.nextInt(-100_000, 100_000) * 0.001));
            texts.add(String.format("%." + random.nextInt(0, 9) + "f", random.nextDouble(-1e6, 1e6)));
        }
        for (String t : texts) {
            assertThat(Double.doubleToRawLongBits(parseDouble(t)))
                    .as(t).isEqualTo(Double.doubleToRawLongBits(Double.parseDouble(t)));
        }
    }

    @Test
    void shouldRefuseWhatTheJdkRefuses() {
        for (String bad : List.of("", " ", "-", ".", "1e", "1..2", "1,5", "abc", "1.5x", "--1")) {
            assertThatThrownBy(() -> parseDouble(bad)).as(bad).isInstanceOf(NumberFormatException.class);
        }
        for (String bad : List.of("", "-", "1.0", "99999999999999999999", "12a")) {
            assertThatThrownBy(() -> parseLong(bad)).as(bad).isInstanceOf(NumberFormatException.class);
        }
    }

    @Test
    void shouldReadLongsAsTheJdkDoes() {
        for (String t : List.of("0", "-0", "+17", " 42 ", "-123456789012345678", "9223372036854775807",
                "-9223372036854775808", "\u0661\u0662")) {
            assertThat(parseLong(t)).as(t).isEqualTo((double) Long.parseLong(t.trim()));
        }
    }
}
