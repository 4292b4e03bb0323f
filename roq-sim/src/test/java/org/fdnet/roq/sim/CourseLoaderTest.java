package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CourseLoaderTest {
    @Test
    void shouldLoadEveryBuiltInCourse() throws Exception {
        for (String name : CourseLoader.BUILT_IN) {
            Course course = CourseLoader.resolve(name);
            assertThat(course.name()).isEqualTo(name);
        }
        Course fragile = CourseLoader.resolve("fragile");
        assertThat(fragile.terrain()).isEqualTo(TerrainKind.RUBBLE);
        assertThat(fragile.fragileCells()).hasSize(4);
        assertThat(fragile.fragileCells().get(0).strength()).isEqualTo(40);
    }

    @Test
    void shouldReadAFileWithCommentsAndFragileCells(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("my.course");
        Files.writeString(file, "# a test course\nname = crossing\nterrain = slope  # up\nslope = 12\nstart = -1 0.2\n"
                + "fragile = 0.5 0 0.2 0.2 0.03 60\n");
        Course course = CourseLoader.load(file);
        assertThat(course.name()).isEqualTo("crossing");
        assertThat(course.terrain()).isEqualTo(TerrainKind.SLOPE);
        assertThat(course.slopeDegrees()).isEqualTo(12);
        assertThat(course.startX()).isEqualTo(-1);
        assertThat(course.startY()).isEqualTo(0.2);
        assertThat(course.fragileCells()).containsExactly(new FragileCell(0.5, 0, 0.2, 0.2, 0.03, 60));
    }

    @Test
    void shouldNameTheFileAndLineOfABadValue() {
        assertThatThrownBy(() -> CourseLoader.parse("bad.course", "name = x\nterrain = rubbel\n"))
                .isInstanceOf(CourseFormatException.class)
                .hasMessage("bad.course:2: unknown terrain 'rubbel' (flat, slope or rubble)");
        assertThatThrownBy(() -> CourseLoader.parse("bad.course", "slope = steep\n"))
                .hasMessage("bad.course:1: slope: not a number: 'steep'");
        assertThatThrownBy(() -> CourseLoader.parse("bad.course", "\n\nfragile = 1 2 3\n"))
                .hasMessage("bad.course:3: expected fragile = x y sizeX sizeY height strength, found '1 2 3'");
        assertThatThrownBy(() -> CourseLoader.parse("bad.course", "fragile = 0 0 0.2 0.2 0.03 -5\n"))
                .hasMessage("bad.course:1: fragile cell strength must be > 0 N, was -5.0");
        assertThatThrownBy(() -> CourseLoader.parse("bad.course", "colour = red\n"))
                .hasMessageStartingWith("bad.course:1: unknown key 'colour'");
        assertThatThrownBy(() -> CourseLoader.parse("bad.course", "start = 9 0\n"))
                .hasMessage("bad.course: start 9.0 0.0 lies outside the course");
    }

    @Test
    void shouldNameAMissingFile(@TempDir Path dir) {
        Path missing = dir.resolve("nope.course");
        assertThatThrownBy(() -> CourseLoader.resolve(missing.toString()))
                .isInstanceOf(CourseFormatException.class)
                .hasMessageStartingWith(missing + ": no such course file (built-in courses: flat, slope, rubble, fragile, crossing)");
    }

    @Test
    void shouldBuildTheSameRubbleFromTheSameSeedAndOtherRubbleFromAnother() {
        Heightfield a = Heightfield.of(Course.rubble(1));
        Heightfield b = Heightfield.of(Course.rubble(1));
        Heightfield c = Heightfield.of(Course.rubble(2));
        assertThat(a.toArray()).isEqualTo(b.toArray());
        assertThat(a.toArray()).isNotEqualTo(c.toArray());
        assertThat(a.maxHeight()).isGreaterThan(0.03).isLessThanOrEqualTo(0.06);
        assertThat(a.heightAt(-1.5, 0)).as("clear start").isZero();
    }
}
