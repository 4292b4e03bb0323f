package org.fdnet.hi.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.fdnet.testing.RealDisplay;
import org.fdnet.testing.RealDisplayExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/** The editor's Live → Run on the simulated RoQ and Stop, on a real X display (Xvfb in CI) with real MuJoCo. */
@ExtendWith(RealDisplayExtension.class)
class RunOnSimulatorGuiTest {
    @Test
    void shouldRunRoqStandOnTheSimulatorFromTheEditorShowItsSensorsChangingAndStopIt(RealDisplay display,
                                                                                   @TempDir Path dir)
            throws Exception {
        String output = EditorWindowGuiTest.runScenario(display.java(RunOnSimulatorScenario.class), dir);
        assertThat(output).contains("SCENARIO PASSED");
    }
}
