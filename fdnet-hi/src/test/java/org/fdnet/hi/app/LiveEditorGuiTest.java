package org.fdnet.hi.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.fdnet.testing.RealDisplay;
import org.fdnet.testing.RealDisplayExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/**
 * Live mode on a real X display (Xvfb in CI), against a network running in the scenario's JVM. With
 * {@code -Dfdnet.hi.images=docs/images} the screenshots go to the user guide's images.
 */
@ExtendWith(RealDisplayExtension.class)
class LiveEditorGuiTest {
    private static final String[] SHOTS = {"hi-live.png", "hi-live-refused.png", "hi-live-self-organised.png",
        "hi-live-deploy.png", "hi-live-offline.png", "hi-live-plot.png"};

    @Test
    void shouldEditLivePlotRefuseFollowTheNetworkManageModulesDeployAllOrNothingAndGoOffline(RealDisplay display,
            @TempDir Path dir) throws Exception {
        String chosen = System.getProperty("fdnet.hi.images");
        Path images = chosen == null ? dir : Path.of(chosen).toAbsolutePath();
        String output = EditorWindowGuiTest.runScenario(display.java(LiveEditorScenario.class, images.toString()), dir);
        assertThat(output).contains("SCENARIO PASSED");
        for (String shot : SHOTS) {
            assertThat(images.resolve(shot)).as(shot).isNotEmptyFile();
        }
    }
}
