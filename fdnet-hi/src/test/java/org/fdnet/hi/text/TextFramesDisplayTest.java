package org.fdnet.hi.text;

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

/** The three text-based frames under a real X display, typed into key by key ({@link TextFramesScenario}). */
@ExtendWith(RealDisplayExtension.class)
@Timeout(value = 150, unit = TimeUnit.SECONDS)
class TextFramesDisplayTest {
    @TempDir
    Path folder;

    @Test
    void shouldKeepTheFramesAndTheNetworkConsistentWhileTheUserTypes(RealDisplay display) throws Exception {
        Process p = display.java(TextFramesScenario.class, folder.toString()).redirectErrorStream(true).start();
        try {
            assertThat(p.waitFor(120, TimeUnit.SECONDS)).as("scenario finished").isTrue();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(out).as(out).contains("STEP existing name loads node and Update",
                    "STEP declared parameters listed and offered",
                    "STEP connection fields offer only existing nodes", "STEP deleting a node deletes its connections",
                    "STEP frames refresh on changes from elsewhere", "STEP network renamed from the Network frame",
                    "STEP rename to a used name asks merge or replace", "STEP all passed");
            assertThat(p.exitValue()).as(out).isZero();
        } finally {
            if (p.isAlive()) {
                p.destroyForcibly();
            }
        }
        for (String name : new String[] {"text-network.png", "text-basic-module.png", "text-advanced-module.png",
                "text-advanced-connections.png"}) {
            BufferedImage shot = ImageIO.read(folder.resolve(name).toFile());
            assertThat(shot.getWidth()).as(name).isGreaterThan(300);
            // kept for the user guide (docs/images/ is copied from here)
            Files.copy(folder.resolve(name), Path.of("target", name), StandardCopyOption.REPLACE_EXISTING);
        }
    }
}
