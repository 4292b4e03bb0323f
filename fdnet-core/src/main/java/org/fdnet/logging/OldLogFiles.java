package org.fdnet.logging;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * Keeps the log folder from filling up: every {@code fdnet} command writes its own {@code fdnet-*.log}, so
 * before a new one is created the oldest are deleted until {@code keep - 1} remain (with the new one: the
 * newest {@code keep}). Only files named {@code fdnet-*.log} are touched, and never the file of a command
 * still running (its process id ends the name). A file that cannot be deleted is named on the terminal with
 * the reason and left in place.
 */
final class OldLogFiles {
    static final int DEFAULT_KEPT = 20;

    private final Path folder;
    private final int keep;
    private final PrintStream terminal;

    OldLogFiles(Path folder, int keep, PrintStream terminal) {
        if (keep < 1) {
            throw new IllegalArgumentException("fdnet.logFilesKept must be at least 1, was " + keep);
        }
        this.folder = folder;
        this.keep = keep;
        this.terminal = terminal;
    }

    /** Deletes the oldest log files so that, with the one about to be created, {@code keep} remain. */
    int pruneBeforeNewFile() {
        if (!Files.isDirectory(folder)) {
            return 0;
        }
        List<Path> logs = new ArrayList<>();
        try (DirectoryStream<Path> files = Files.newDirectoryStream(folder, "fdnet-*.log")) {
            files.forEach(logs::add);
        } catch (IOException e) {
            terminal.println("fdnet: cannot list the log folder " + folder + " to delete old log files (" + e.getMessage() + ")");
            return 0;
        }
        logs.sort(Comparator.comparing(OldLogFiles::modified).thenComparing(Path::getFileName).reversed());
        int deleted = 0;
        for (Path old : logs.subList(Math.min(logs.size(), keep - 1), logs.size())) {
            if (writerStillRunning(old)) {
                continue;
            }
            try {
                Files.deleteIfExists(old);
                deleted++;
            } catch (IOException e) {
                terminal.println("fdnet: cannot delete the old log file " + old + " (" + e.getMessage() + ")");
            }
        }
        return deleted;
    }

    /**
     * A command still running keeps its file, however old: the name ends with its process id
     * ({@code fdnet-<time>-<pid>.log}); a long-running {@code fdnet logger} would otherwise lose its log.
     */
    static boolean writerStillRunning(Path file) {
        String name = file.getFileName().toString();
        int dash = name.lastIndexOf('-');
        int dot = name.lastIndexOf('.');
        if (dash < 0 || dot <= dash + 1) {
            return false;
        }
        try {
            long pid = Long.parseLong(name.substring(dash + 1, dot));
            return ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false);
        } catch (NumberFormatException e) {
            return false; // not a name fdnet gave: no process to wait for
        }
    }

    private static FileTime modified(Path file) {
        try {
            return Files.getLastModifiedTime(file);
        } catch (IOException e) {
            return FileTime.fromMillis(0); // vanished meanwhile (another fdnet pruning): oldest, delete is a no-op
        }
    }
}
