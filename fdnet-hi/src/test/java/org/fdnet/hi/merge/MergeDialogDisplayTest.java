package org.fdnet.hi.merge;

import static org.assertj.core.api.Assertions.assertThat;

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

/** The Merge/Replace dialog under a real X display, answered with each choice ({@link MergeDialogScenario}). */
@ExtendWith(RealDisplayExtension.class)
@Timeout(value = 150, unit = TimeUnit.SECONDS)
class MergeDialogDisplayTest {
    @TempDir
    Path folder;

    @Test
    void shouldReplaceOrMergeWithEachParameterPolicyAsTheUserAnswers(RealDisplay display) throws Exception {
        Process p = display.java(MergeDialogScenario.class, folder.toString()).redirectErrorStream(true).start();
        try {
            assertThat(p.waitFor(120, TimeUnit.SECONDS)).as("scenario finished").isTrue();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(out).as(out).contains("STEP replace", "STEP merge FIRST", "STEP merge SECOND", "STEP merge BOTH",
                    "STEP merge refused between kinds, cancel changes nothing", "STEP all passed");
            assertThat(p.exitValue()).as(out).isZero();
        } finally {
            if (p.isAlive()) {
                p.destroyForcibly();
            }
        }
        Path png = folder.resolve("merge-replace-dialog.png");
        assertThat(ImageIO.read(png.toFile()).getWidth()).isGreaterThan(300);
        Files.copy(png, Path.of("target", "merge-replace-dialog.png"), StandardCopyOption.REPLACE_EXISTING);
    }
}
