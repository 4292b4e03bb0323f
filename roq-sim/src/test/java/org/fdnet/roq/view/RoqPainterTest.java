package org.fdnet.roq.view;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.FragileCell;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The painter draws what the snapshot says: the body, feet in contact, intact and broken cells. */
class RoqPainterTest {
    static final int BODY = 0x3B5B92;
    static final int CONTACT = 0x2E9E44;
    static final int CELL = 0xE39B2D;
    static final int BROKEN = 0x5A2A0A;

    @Test
    void shouldDrawTheRobotContactsAndTheCellsAsTheSnapshotSays(@TempDir Path dir) throws Exception {
        double[] foot = RoqGeometry.footInBody(0, RoqGeometry.STANDING_POSE[0], RoqGeometry.STANDING_POSE[1],
                RoqGeometry.STANDING_POSE[2], new double[3]);
        Course course = Course.flat().withFragileCells(List.of(
                new FragileCell(foot[0], foot[1], 0.16, 0.16, 0.04, 30),     // under the front-left foot: breaks
                new FragileCell(1.2, 0.5, 0.2, 0.2, 0.03, 40)));            // away from the robot: stays
        try (RoqSimulator sim = RoqSimulator.open(course, SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.read(s);
            BufferedImage before = paint(s, sim);
            sim.step(1000);
            sim.read(s);
            assertThat(s.isCellBroken(0)).isTrue();
            assertThat(s.isCellBroken(1)).isFalse();
            BufferedImage after = paint(s, sim);

            assertThat(count(before, BODY)).as("body drawn").isGreaterThan(1000);
            assertThat(count(before, BROKEN)).as("nothing broken yet").isZero();
            assertThat(count(after, BROKEN)).as("the broken cell drawn open").isGreaterThan(100);
            assertThat(count(after, CELL)).as("the intact cell still drawn").isGreaterThan(100);
            assertThat(count(after, CONTACT)).as("feet in contact drawn green").isGreaterThan(50);

            Path png = dir.resolve("roq.png");
            RoqScreenshot.write(s, sim.heightfield(), 900, 600, png);
            BufferedImage read = ImageIO.read(png.toFile());
            assertThat(read.getWidth()).isEqualTo(900);
            assertThat(Files.size(png)).isGreaterThan(1000);
        }
    }

    private static BufferedImage paint(SensorSnapshot s, RoqSimulator sim) {
        BufferedImage image = new BufferedImage(1200, 760, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        new RoqPainter().paint(g, s, sim.heightfield(), new Rectangle(0, 0, 1200, 760));
        g.dispose();
        return image;
    }

    private static int count(BufferedImage image, int rgb) {
        int n = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                if ((image.getRGB(x, y) & 0xFFFFFF) == rgb) {
                    n++;
                }
            }
        }
        return n;
    }
}
