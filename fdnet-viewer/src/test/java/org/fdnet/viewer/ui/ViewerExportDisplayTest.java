package org.fdnet.viewer.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.fdnet.logger.export.McapReaders;
import org.fdnet.testing.RealDisplay;
import org.fdnet.testing.RealDisplayExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/**
 * The viewer's Export… under a real display ({@link ExportScenario}): the two selected nodes' 4,000 values written as
 * MCAP, which Python's mcap and @mcap/core read back whole, and as CSV, which pandas loads with one line per value.
 */
@ExtendWith(RealDisplayExtension.class)
@Timeout(value = 240, unit = TimeUnit.SECONDS)
class ViewerExportDisplayTest {
    @TempDir
    Path folder;

    @Test
    void shouldExportTheSelectedNodesAsMcapAndCsvThatOthersReadersLoad(RealDisplay display) throws Exception {
        McapReaders readers = new McapReaders();
        Process p = display.java(ExportScenario.class, folder.toString()).redirectErrorStream(true).start();
        try {
            boolean done = p.waitFor(200, TimeUnit.SECONDS);
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(done).as(out).isTrue();
            assertThat(out).as(out).contains("STEP window open", "STEP MCAP: exported 4,000 values",
                    "STEP CSV: exported 4,000 values", "STEP all passed");
            assertThat(p.exitValue()).as(out).isZero();
        } finally {
            if (p.isAlive()) {
                p.destroyForcibly();
            }
        }
        Path mcap = folder.resolve("export.mcap");
        assertThat(readers.python(mcap, null, "/Pose/pitch", "/Pose/歩幅")).startsWith("python mcap: OK 4000 messages, 3 channels");
        assertThat(readers.typescript(mcap, null, "/Pose/pitch", "/Pose/歩幅")).startsWith("@mcap/core: OK 4000 messages");
        assertThat(readers.pandasShape(folder.resolve("export.csv"))).isEqualTo("4000 5");
    }
}
