package org.fdnet.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.function.Consumer;

/**
 * One run of Maven ({@code mvn} on the PATH) in a folder: every line of its output goes to a log file and to a
 * listener (the progress a command prints); the last lines are kept to show when it fails.
 */
final class MavenRun {
    private static final int KEPT_LINES = 40;

    private final Deque<String> lastLines = new ArrayDeque<>();
    private final List<String> command;
    private int exitCode = -1;

    private MavenRun(List<String> command) {
        this.command = List.copyOf(command);
    }

    /**
     * Runs {@code mvn ARGUMENTS} in {@code directory}, appending its output to {@code log}; returns when it ends.
     *
     * @throws IllegalStateException when mvn cannot be started (the sentence names what to install)
     */
    static MavenRun run(Path directory, List<String> arguments, Path log, Consumer<String> eachLine) {
        List<String> command = new ArrayList<>();
        command.add("mvn");
        command.addAll(arguments);
        MavenRun run = new MavenRun(command);
        Process process;
        try {
            Files.createDirectories(log.toAbsolutePath().getParent());
            process = new ProcessBuilder(command).directory(directory.toFile()).redirectErrorStream(true).start();
        } catch (IOException e) {
            throw new IllegalStateException("cannot run Maven (mvn): " + e.getMessage()
                    + "; install Maven 3.8 or later (Debian: apt-get install maven) and try again", e);
        }
        try (PrintWriter logFile = new PrintWriter(Files.newBufferedWriter(log, StandardCharsets.UTF_8,
                     StandardOpenOption.CREATE, StandardOpenOption.APPEND));
             BufferedReader out = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
            process.getOutputStream().close(); // Maven runs in batch mode (-B): it reads nothing
            logFile.println("$ " + String.join(" ", command) + "   (in " + directory + ")");
            String line;
            while ((line = out.readLine()) != null) {
                logFile.println(line);
                run.keep(line);
                eachLine.accept(line);
            }
            run.exitCode = process.waitFor();
        } catch (IOException e) {
            process.destroyForcibly();
            throw new UncheckedIOException("reading Maven's output", e);
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while Maven ran", e);
        }
        return run;
    }

    private void keep(String line) {
        if (lastLines.size() == KEPT_LINES) {
            lastLines.removeFirst();
        }
        lastLines.addLast(line);
    }

    boolean succeeded() {
        return exitCode == 0;
    }

    int exitCode() {
        return exitCode;
    }

    /** The last lines Maven printed (its error, when it failed). */
    List<String> lastLines() {
        return List.copyOf(lastLines);
    }

    /** True when Maven failed because an artifact it needs is not in the local repository and it ran offline. */
    boolean missedAnArtifactOffline() {
        return !succeeded() && lastLines.stream().anyMatch(l -> l.contains("offline mode")
                || l.contains("has not been downloaded from it before"));
    }

    String commandLine() {
        return String.join(" ", command);
    }
}
