package org.fdnet.logging;

import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import org.slf4j.event.Level;

/**
 * The rules: WARN and ERROR are written to the terminal (stderr, one line each, the cause's message
 * appended) and to the file; INFO (and DEBUG when asked for) to the file only. The file is opened when its
 * first line comes and named on the terminal then, once. If it cannot be opened, the terminal says so once
 * and the lines go to the terminal instead: nothing is lost silently.
 */
final class LogRouting {
    private static final DateTimeFormatter FILE_TIME = DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss");
    private static final DateTimeFormatter LINE_TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss.SSS");

    private final Path file;
    private final Level fileLevel;
    private final PrintStream terminal;
    private final OldLogFiles oldFiles;
    private PrintStream out;
    private boolean openFailed;

    LogRouting(Path file, Level fileLevel, PrintStream terminal) {
        this(file, fileLevel, terminal, null);
    }

    /** @param oldFiles deletes the folder's oldest log files before this one is created (null: none) */
    LogRouting(Path file, Level fileLevel, PrintStream terminal, OldLogFiles oldFiles) {
        this.file = file;
        this.fileLevel = fileLevel;
        this.terminal = terminal;
        this.oldFiles = oldFiles;
    }

    static LogRouting fromSystemProperties() {
        String f = System.getProperty("fdnet.logFile");
        Level level = "debug".equalsIgnoreCase(System.getProperty("fdnet.logLevel")) ? Level.DEBUG : Level.INFO;
        if (f != null) {
            return new LogRouting(Path.of(f), level, System.err); // a file the user named: its folder is theirs
        }
        Path folder = Path.of(System.getProperty("user.home"), ".fdnet", "logs");
        Path file = folder.resolve("fdnet-" + LocalDateTime.now().format(FILE_TIME) + "-" + ProcessHandle.current().pid()
                + ".log");
        int kept = Integer.getInteger("fdnet.logFilesKept", OldLogFiles.DEFAULT_KEPT);
        if (kept < 1) {
            System.err.println("fdnet: fdnet.logFilesKept must be at least 1, was " + kept + "; keeping the newest "
                    + OldLogFiles.DEFAULT_KEPT);
            kept = OldLogFiles.DEFAULT_KEPT;
        }
        return new LogRouting(file, level, System.err, new OldLogFiles(folder, kept, System.err));
    }

    boolean enabled(Level level) {
        return level.toInt() >= fileLevel.toInt();
    }

    synchronized void write(Level level, String logger, String message, Throwable error) {
        if (!enabled(level)) {
            return;
        }
        if (level.toInt() >= Level.WARN.toInt()) {
            terminal.println("fdnet: " + level + " " + shortName(logger) + ": " + message
                    + (error == null ? "" : " (" + error + ")"));
        }
        PrintStream f = file();
        if (f == null) {
            if (level.toInt() < Level.WARN.toInt()) {
                terminal.println("fdnet: " + level + " " + shortName(logger) + ": " + message);
            }
            return;
        }
        f.println(LocalDateTime.now().format(LINE_TIME) + " [" + Thread.currentThread().getName() + "] " + level + " "
                + logger + " - " + message);
        if (error != null) {
            StringWriter trace = new StringWriter();
            error.printStackTrace(new PrintWriter(trace)); // into the log file, not the terminal
            f.print(trace);
        }
        f.flush();
    }

    private PrintStream file() {
        if (out != null || openFailed) {
            return out;
        }
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            if (oldFiles != null) {
                oldFiles.pruneBeforeNewFile();
            }
            out = new PrintStream(Files.newOutputStream(file), false, StandardCharsets.UTF_8);
            terminal.println("fdnet: log file " + file);
        } catch (IOException | RuntimeException e) {
            openFailed = true;
            terminal.println("fdnet: cannot write the log file " + file + " (" + e.getMessage()
                    + "); log lines go to the terminal");
        }
        return out;
    }

    private static String shortName(String logger) {
        int dot = logger.lastIndexOf('.');
        return dot < 0 ? logger : logger.substring(dot + 1);
    }
}
