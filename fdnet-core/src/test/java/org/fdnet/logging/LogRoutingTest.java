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

    @Test
    void shouldKeepOnlyTheNewestLogFilesAndThoseOfRunningCommandsWhenANewOneIsCreated() throws Exception {
        Path logs = Files.createDirectories(folder.resolve("logs"));
        Process ended = new ProcessBuilder("true").start();
        ended.waitFor();
        long endedPid = ended.pid(); // the old runs' commands have ended
        for (int i = 0; i < 25; i++) {
            Path old = Files.writeString(logs.resolve(String.format("fdnet-20261123-0900%02d-%d.log", i, endedPid)), "run " + i);
            Files.setLastModifiedTime(old, java.nio.file.attribute.FileTime.fromMillis(1_000_000L * (i + 1)));
        }
        Path notOurs = Files.writeString(logs.resolve("notes.txt"), "keep me");
        Path running = Files.writeString(logs.resolve("fdnet-20261122-080000-" + ProcessHandle.current().pid() + ".log"),
                "a logger still running");
        Files.setLastModifiedTime(running, java.nio.file.attribute.FileTime.fromMillis(1));
        Path file = logs.resolve("fdnet-20261123-100000-2.log");
        LogRouting routing = new LogRouting(file, Level.INFO, terminal, new OldLogFiles(logs, 20, terminal));
        routing.write(Level.INFO, "org.jacorb.orb", "ORB run", null);

        try (var listed = Files.list(logs)) {
            assertThat(listed.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".log")).sorted().toList())
                    .hasSize(21).contains("fdnet-20261123-100000-2.log", "fdnet-20261123-090024-" + endedPid + ".log",
                            "fdnet-20261123-090006-" + endedPid + ".log")
                    .doesNotContain("fdnet-20261123-090005-" + endedPid + ".log");
        }
        assertThat(notOurs).exists();
        assertThat(running).as("the oldest file, but its command (this JVM) still runs").exists();
        assertThat(Files.readString(file)).contains("ORB run");
    }
}
