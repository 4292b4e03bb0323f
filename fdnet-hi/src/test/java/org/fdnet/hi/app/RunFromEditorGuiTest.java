package org.fdnet.hi.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.fdnet.testing.RealDisplay;
import org.fdnet.testing.RealDisplayExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/** Live → Run and Stop on a real X display (Xvfb in CI): on this machine, and distributed over a real host. */
@ExtendWith(RealDisplayExtension.class)
class RunFromEditorGuiTest {
    @Test
    void shouldRunTheOpenNetworkHereAndDistributedAttachAtOnceAndStopIt(RealDisplay display, @TempDir Path dir)
            throws Exception {
        String output = EditorWindowGuiTest.runScenario(display.java(RunFromEditorScenario.class), dir);
        assertThat(output).contains("SCENARIO PASSED");
    }
}
