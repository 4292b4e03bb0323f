package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.nio.charset.StandardCharsets;
import java.util.Locale;

/**
 * Fuzzes {@link CourseLoader#parse}: any text is a course or a {@link CourseFormatException} naming the file
 * (and, for a bad line, the line) — never another exception. A course it accepts must build what the simulator
 * builds from it (the {@link Heightfield} and the MJCF model) with finite heights, and reads back equal from its
 * own {@code key = value} text. Seeds (the built-in courses) and kept findings:
 * {@code src/test/resources/org/fdnet/roq/sim/CourseFileFuzzTestInputs/}.
 */
class CourseFileFuzzTest {
    private static final String SOURCE = "fuzz.course";

    @FuzzTest(maxDuration = "10m")
    void shouldLoadOrRefuseTheCourse(byte[] input) throws CourseFormatException {
        Course course;
        try {
            course = CourseLoader.parse(SOURCE, new String(input, StandardCharsets.UTF_8));
        } catch (CourseFormatException refused) {
            assertThat(refused.getMessage()).startsWith(SOURCE + ":");
            return;
        }
        Heightfield ground = Heightfield.of(course);
        assertThat(ground.maxHeight()).isFinite();
        assertThat(ground.minHeight()).isFinite();
        assertThat(MjcfWriter.write(course, ground, 0.3)).contains("<mujoco");
        assertThat(CourseLoader.parse("again.course", text(course))).isEqualTo(course);
    }

    /** The course as a file says it: every key, numbers as Java prints them (which read back exactly). */
    private static String text(Course c) {
        StringBuilder s = new StringBuilder()
                .append("name = ").append(c.name()).append('\n')
                .append("terrain = ").append(c.terrain().name().toLowerCase(Locale.ROOT)).append('\n')
                .append("length = ").append(c.length()).append('\n')
                .append("width = ").append(c.width()).append('\n')
                .append("cell = ").append(c.cellSize()).append('\n')
                .append("slope = ").append(c.slopeDegrees()).append('\n')
                .append("rubble.height = ").append(c.rubbleHeight()).append('\n')
                .append("rubble.block = ").append(c.rubbleBlock()).append('\n')
                .append("seed = ").append(c.seed()).append('\n')
                .append("start = ").append(c.startX()).append(' ').append(c.startY()).append('\n');
        for (FragileCell f : c.fragileCells()) {
            s.append("fragile = ").append(f.x()).append(' ').append(f.y()).append(' ').append(f.sizeX()).append(' ')
                    .append(f.sizeY()).append(' ').append(f.height()).append(' ').append(f.strength()).append('\n');
        }
        return s.toString();
    }
}
