package org.fdnet.logger.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.fdnet.logger.PostgresFixture;
import org.fdnet.testing.RealDisplay;
import org.fdnet.testing.RealDisplayExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/** The configuration panel under a real X display: refuse, start, show a core live, screenshot, stop. */
@ExtendWith(RealDisplayExtension.class)
@Timeout(value = 150, unit = TimeUnit.SECONDS)
class ConfigPanelDisplayTest {
    @TempDir
    Path folder;

    @Test
    void shouldStartShowLiveStatusAndStopTheLoggerFromThePanel(RealDisplay display) throws Exception {
        try (PostgresFixture pg = new PostgresFixture(folder)) {
            Path png = folder.resolve("panel.png");
            Process p = display.java(ConfigPanelScenario.class, pg.target().url(), pg.target().user(),
                    folder.resolve("logger.properties").toString(), png.toString()).redirectErrorStream(true).start();
            try {
                assertThat(p.waitFor(120, TimeUnit.SECONDS)).as("scenario finished").isTrue();
                String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
                assertThat(out).as(out).contains("STEP started", "STEP core shown", "STEP stopped", "STEP all passed");
                assertThat(p.exitValue()).as(out).isZero();
            } finally {
                if (p.isAlive()) {
                    p.destroyForcibly();
                }
            }
            BufferedImage shot = ImageIO.read(png.toFile());
            assertThat(shot.getWidth()).isGreaterThan(600);
            assertThat(folder.resolve("logger.properties")).content().contains("writer.batchSize=500");
            // Kept to look at: the panel running with a core connected.
            java.nio.file.Files.copy(png, Path.of("target", "logger-config-running.png"),
                    java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
    }
}
