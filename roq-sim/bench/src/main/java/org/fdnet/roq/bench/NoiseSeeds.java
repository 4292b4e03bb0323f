package org.fdnet.roq.bench;

import java.util.Arrays;

/** The {@code --noise} option of {@code fdnet bench roq}: a range {@code FROM-TO} or a comma-separated list of seeds. */
final class NoiseSeeds {
    /** The most seeds one sweep takes. */
    static final int MOST = 1000;

    private NoiseSeeds() {
    }

    /** The seeds {@code text} names, or none when it is malformed, empty, backwards or longer than {@link #MOST}. */
    static long[] parse(String text) {
        String t = text == null ? "" : text.strip();
        try {
            if (t.matches("\\d+-\\d+")) {
                String[] ends = t.split("-");
                long from = Long.parseLong(ends[0]);
                long to = Long.parseLong(ends[1]);
                if (from > to || to - from >= MOST) {
                    return new long[0];
                }
                long[] seeds = new long[(int) (to - from + 1)];
                for (int i = 0; i < seeds.length; i++) {
                    seeds[i] = from + i;
                }
                return seeds;
            }
            if (t.matches("\\d+(\\s*,\\s*\\d+)*")) {
                long[] seeds = Arrays.stream(t.split(",")).map(String::strip).mapToLong(Long::parseLong).toArray();
                return seeds.length <= MOST ? seeds : new long[0];
            }
        } catch (NumberFormatException tooLarge) {
            return new long[0];
        }
        return new long[0];
    }
}
