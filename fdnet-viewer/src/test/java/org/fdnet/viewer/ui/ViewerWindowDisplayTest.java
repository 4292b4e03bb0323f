package org.fdnet.viewer.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.fdnet.testing.RealDisplay;
import org.fdnet.testing.RealDisplayExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/**
 * The viewer window under a real X display (see {@link ViewerScenario}): plots per unit on one linked time axis,
 * every control visible at the default size, series added and refused by unit, layouts saved and reopened, replay,
 * RoQ's ready layout, and {@code fdnet viewer --screenshot}.
 */
@ExtendWith(RealDisplayExtension.class)
@Timeout(value = 240, unit = TimeUnit.SECONDS)
class ViewerWindowDisplayTest {
    @TempDir
    Path folder;

    @Test
    void shouldPlotOnLinkedAxesKeepUnitsApartReopenLayoutsReplayAndWriteAScreenshot(RealDisplay display) throws Exception {
        Path window = folder.resolve("window.png");
        Path command = folder.resolve("command.png");
        Process p = display.java(ViewerScenario.class, window.toString(), command.toString()).redirectErrorStream(true).start();
        try {
            boolean done = p.waitFor(200, TimeUnit.SECONDS);
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(done).as(out).isTrue();
            assertThat(out).as(out).contains("STEP live values drawn", "STEP one plot per unit", "STEP Japanese name legible",
                    "STEP every control visible at 1200x820", "STEP paused, zoomed and cursor linked",
                    "STEP mixed units refused", "STEP series added to a new plot in m", "STEP dragged into a plot", "STEP replay",
                    "STEP layout reopened", "STEP RoQ layout", "STEP command screenshot", "STEP unknown node refused",
                    "STEP all passed");
            assertThat(p.exitValue()).as(out).isZero();
        } finally {
            if (p.isAlive()) {
                p.destroyForcibly();
            }
        }
        BufferedImage shot = ImageIO.read(command.toFile());
        assertThat(shot.getWidth()).isGreaterThan(800);
        assertThat(ImageIO.read(window.toFile()).getHeight()).isGreaterThan(500);
        Files.copy(command, Path.of("target", "viewer.png"), StandardCopyOption.REPLACE_EXISTING);
        Files.copy(folder.resolve("viewer-roq.png"), Path.of("target", "viewer-roq.png"), StandardCopyOption.REPLACE_EXISTING);
        Files.copy(folder.resolve("viewer-roq-no-legend.png"), Path.of("target", "viewer-roq-no-legend.png"),
                StandardCopyOption.REPLACE_EXISTING);
    }
}
