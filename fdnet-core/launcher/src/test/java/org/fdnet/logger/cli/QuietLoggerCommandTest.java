package org.fdnet.logger.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fdnet.cli.FdnetCommand;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code fdnet logger} as a user starts it, in its own process: the terminal shows the command's own lines
 * and the log file's name; the embedded PostgreSQL's start-up and every INFO line are in the log file.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class QuietLoggerCommandTest {
    @TempDir
    Path folder;

    @Test
    void shouldStartTheLoggerWithOnlyItsOwnLinesOnTheTerminal() throws Exception {
        Path config = Files.writeString(folder.resolve("logger.properties"), "database.embeddedDirectory="
                + folder.resolve("db") + "\nreceiver.port=0\nsender.port=0\n");
        Path logFile = folder.resolve("fdnet.log");
        Path terminal = folder.resolve("terminal.txt");
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Dfdnet.logFile=" + logFile, "-cp", System.getProperty("java.class.path"), FdnetCommand.class.getName(),
                "logger", "--config", config.toString(), "--status-every", "1")
                .redirectErrorStream(true).redirectOutput(terminal.toFile()).start();
        try {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(90);
            while (!read(terminal).contains("| db connected") && p.isAlive() && System.nanoTime() < deadline) {
                Thread.sleep(100);
            }
        } finally {
            p.destroy(); // SIGTERM: the command stops the logger and exits
            if (!p.waitFor(30, TimeUnit.SECONDS)) {
                p.destroyForcibly().waitFor();
            }
        }
        List<String> lines = read(terminal).lines().toList();
        assertThat(lines).first().isEqualTo("fdnet: log file " + logFile);
        assertThat(lines).filteredOn(l -> l.startsWith("fdnet logger: cores -> 127.0.0.1:")).hasSize(1);
        assertThat(lines).anyMatch(l -> l.contains("| db connected"));
        assertThat(lines).allMatch(l -> l.startsWith("fdnet logger:") || l.startsWith("cache ")
                || l.equals("fdnet: log file " + logFile));
        assertThat(Files.readString(logFile)).contains("INFO io.zonky.test.db.postgres.embedded.EmbeddedPostgres")
                .contains("fsync on").contains("database system is ready to accept connections");
    }

    private static String read(Path file) throws IOException {
        return Files.exists(file) ? Files.readString(file, StandardCharsets.UTF_8) : "";
    }
}
