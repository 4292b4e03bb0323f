package org.fdnet.roq.view;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.fdnet.testing.RealDisplay;
import org.fdnet.testing.RealDisplayExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/** {@code fdnet demo --gui} on a real X display: the window opens, paints the robot, updates, and its screenshot. */
@ExtendWith(RealDisplayExtension.class)
@Timeout(value = 180, unit = TimeUnit.SECONDS)
class DemoWindowDisplayTest {
    static final int BODY = 0x3B5B92;

    @TempDir
    Path folder;

    @Test
    void shouldShowTheWalkingRobotLiveAndWriteTheWindowAsScreenshot(RealDisplay display) throws Exception {
        Path network = Path.of("..", "networks", "roq-walk.fdn").toAbsolutePath().normalize();
        Path shot = folder.resolve("demo.png");
        Path screen = folder.resolve("screen.png");
        Process p = display.java(DemoWindowScenario.class, network.toString(), shot.toString(), screen.toString())
                .redirectErrorStream(true).start();
        try {
            boolean done = p.waitFor(150, TimeUnit.SECONDS);
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(done).as(out).isTrue();
            assertThat(out).as(out).contains("STEP window open", "STEP window updates",
                    "STEP every label whole", "STEP screen captured",
                    "STEP all passed", "summary: walked", "margin", "course: cells broken by probes",
                    "loaded-foot breakthroughs", "off the course line max", "heading error max");
            assertThat(p.exitValue()).as(out).isZero();
        } finally {
            if (p.isAlive()) {
                p.destroyForcibly();
            }
        }
        BufferedImage onScreen = ImageIO.read(screen.toFile());
        assertThat(count(onScreen, BODY)).as("the robot's body painted on the screen").isGreaterThan(500);
        BufferedImage png = ImageIO.read(shot.toFile());
        assertThat(png.getWidth()).isGreaterThan(800);
        assertThat(count(png, BODY)).as("the robot's body in the screenshot").isGreaterThan(500);
        assertThat(count(png, RoqPainter.SUPPORT.getRGB() & 0xFFFFFF)).as("the support polygon's outline").isGreaterThan(20);
    }

    private static int count(BufferedImage img, int rgb) {
        int n = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                if ((img.getRGB(x, y) & 0xFFFFFF) == rgb) {
                    n++;
                }
            }
        }
        return n;
    }
}
