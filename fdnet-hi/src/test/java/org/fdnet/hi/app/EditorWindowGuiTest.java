package org.fdnet.hi.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.fdnet.testing.RealDisplay;
import org.fdnet.testing.RealDisplayExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/** The editor on a real X display (Xvfb in CI): the round trip of the "Done when". */
@ExtendWith(RealDisplayExtension.class)
class EditorWindowGuiTest {
    private static final Path NETWORKS = Path.of("..", "networks");

    @Test
    void shouldOpenEditInBothViewsMergeUndoSaveAndReopenUnchanged(RealDisplay display, @TempDir Path dir) throws Exception {
        Path fdn = dir.resolve("roq-motion.fdn");
        Files.copy(NETWORKS.resolve("roq-motion.fdn"), fdn);
        Files.copy(NETWORKS.resolve("roq-motion.fdg"), dir.resolve("roq-motion.fdg"));
        String output = runScenario(display.java(EditorRoundTripScenario.class, fdn.toString()), dir);
        assertThat(output).contains("SCENARIO PASSED");
    }

    @Test
    void shouldShowEveryControlWholeAtTheDefaultSize(RealDisplay display, @TempDir Path dir) throws Exception {
        Path fdn = dir.resolve("roq-rubble.fdn");
        Files.copy(NETWORKS.resolve("roq-rubble.fdn"), fdn);
        Files.copy(NETWORKS.resolve("roq-rubble.fdg"), dir.resolve("roq-rubble.fdg"));
        String output = runScenario(display.java(EditorVisibilityScenario.class, fdn.toString()), dir);
        assertThat(output).contains("SIZE 1280x800", "SCENARIO PASSED").doesNotContain("PROBLEM");
    }

    @Test
    void shouldOpenAFileWithProblemsReadOnlyAndJumpToEachProblemsLine(RealDisplay display, @TempDir Path dir) throws Exception {
        Path bad = dir.resolve("bad.fdn");
        Files.writeString(bad, String.join("\n", "<?xml version=\"1.0\"?>", "<cnet name=\"bad\">",
                "  <dstructure>", "    <name>a</name>", "  </dstructure>", "  <pstructure>", "    <name>b</name>",
                "    <host>localhost</host>", "  </pstructure>", "  <connection>", "    <read><data>nowhere</data><proc>b</proc></read>",
                "  </connection>", "</cnet>", ""));
        String output = runScenario(display.java(ProblemFileScenario.class, bad.toString()), dir);
        assertThat(output).contains("SCENARIO PASSED");
    }

    @Test
    void shouldShowEveryJapaneseNameOfAnEucJpNetworkInALegibleFont(RealDisplay display, @TempDir Path dir) throws Exception {
        String output = runScenario(display.java(JapaneseNamesScenario.class, NETWORKS.resolve("arms-ja.fdn").toString()), dir);
        assertThat(output).contains("SCENARIO PASSED");
    }

    static String runScenario(ProcessBuilder pb, Path dir) throws IOException, InterruptedException {
        Path log = dir.resolve("scenario.log");
        Process p = pb.redirectErrorStream(true).redirectOutput(log.toFile()).start();
        try {
            boolean ended = p.waitFor(150, TimeUnit.SECONDS);
            String output = Files.readString(log, StandardCharsets.UTF_8);
            assertThat(ended).as("scenario ended within 150 s; output:%n%s", output).isTrue();
            assertThat(p.exitValue()).as("scenario exit code; output:%n%s", output).isZero();
            return output;
        } finally {
            p.destroyForcibly();
        }
    }
}
