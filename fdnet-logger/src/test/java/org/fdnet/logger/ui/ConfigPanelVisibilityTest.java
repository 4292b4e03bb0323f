package org.fdnet.logger.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.fdnet.testing.RealDisplay;
import org.fdnet.testing.RealDisplayExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/**
 * The configuration window as a person sees it at its default size: every field on screen, a bad value refused at
 * its field, and a saved setting shown again by the next window opened on the same file.
 */
@ExtendWith(RealDisplayExtension.class)
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class ConfigPanelVisibilityTest {
    @TempDir
    Path folder;

    @Test
    void shouldShowEveryFieldRefuseABadValueAtItsFieldAndKeepASavedSettingAcrossARestart(RealDisplay display)
            throws Exception {
        Path file = folder.resolve("logger.properties");
        Path png = folder.resolve("logger-config.png");
        String first = run(display, file.toString(), "change", png.toString());
        assertThat(first).contains("SIZE 1024x700", "VISIBLE").doesNotContain("PROBLEM");
        assertThat(first).contains("REASON writer.batchSize must be in [1, 1000000], was 0", "OUTLINE error",
                "START REFUSED writer.batchSize must be in [1, 1000000], was 0", "HELP events per COPY transaction",
                "SAVED true");
        assertThat(file).content().contains("writer.batchSize=750");

        String second = run(display, file.toString(), "reopen");
        assertThat(second).contains("VISIBLE", "BATCH 750");
        java.nio.file.Files.copy(png, Path.of("target", "logger-config.png"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
    }

    private static String run(RealDisplay display, String... args) throws Exception {
        Process p = display.java(ConfigPanelVisibilityScenario.class, args).redirectErrorStream(true).start();
        try {
            assertThat(p.waitFor(60, TimeUnit.SECONDS)).as("window scenario finished").isTrue();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(p.exitValue()).as(out).isZero();
            return out;
        } finally {
            if (p.isAlive()) {
                p.destroyForcibly();
            }
        }
    }
}
