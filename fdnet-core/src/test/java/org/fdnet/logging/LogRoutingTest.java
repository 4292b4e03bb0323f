package org.fdnet.logging;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.slf4j.event.Level;

class LogRoutingTest {
    @TempDir
    Path folder;

    private final ByteArrayOutputStream terminalBytes = new ByteArrayOutputStream();
    private final PrintStream terminal = new PrintStream(terminalBytes, true, StandardCharsets.UTF_8);

    private String terminal() {
        return terminalBytes.toString(StandardCharsets.UTF_8);
    }

    @Test
    void shouldKeepInfoOffTheTerminalAndNameTheLogFileOnce() throws IOException {
        Path file = folder.resolve("logs/fdnet.log");
        LogRouting routing = new LogRouting(file, Level.INFO, terminal);
        routing.write(Level.INFO, "io.zonky.test.db.postgres.embedded.EmbeddedPostgres", "postmaster started", null);
        routing.write(Level.INFO, "org.jacorb.orb", "ORB run", null);
        routing.write(Level.DEBUG, "org.fdnet.x", "not logged at info", null);

        assertThat(terminal()).isEqualTo("fdnet: log file " + file + System.lineSeparator());
        String log = Files.readString(file);
        assertThat(log).contains("INFO io.zonky.test.db.postgres.embedded.EmbeddedPostgres - postmaster started")
                .contains("org.jacorb.orb - ORB run").doesNotContain("not logged at info");
    }

    @Test
    void shouldShowWarningsOnTheTerminalWithTheirCauseAndTheTraceInTheFile() throws IOException {
        Path file = folder.resolve("fdnet.log");
        LogRouting routing = new LogRouting(file, Level.INFO, terminal);
        routing.write(Level.WARN, "org.fdnet.logger.writer.BatchWriter", "database write failed",
                new IllegalStateException("connection refused"));

        assertThat(terminal()).contains("fdnet: WARN BatchWriter: database write failed"
                + " (java.lang.IllegalStateException: connection refused)").doesNotContain("\tat ");
        assertThat(Files.readString(file)).contains("database write failed").contains("\tat ");
    }

    @Test
    void shouldSendTheLinesToTheTerminalWhenTheFileCannotBeWritten() throws IOException {
        Path blocker = Files.writeString(folder.resolve("not-a-folder"), "x");
        LogRouting routing = new LogRouting(blocker.resolve("fdnet.log"), Level.INFO, terminal);
        routing.write(Level.INFO, "org.jacorb.orb", "ORB run", null);
        routing.write(Level.INFO, "org.jacorb.orb", "ORB still running", null);

        assertThat(terminal()).contains("cannot write the log file " + blocker.resolve("fdnet.log"))
                .contains("ORB run").contains("ORB still running");
        assertThat(terminal().split("cannot write", -1)).hasSize(2);
    }
}
