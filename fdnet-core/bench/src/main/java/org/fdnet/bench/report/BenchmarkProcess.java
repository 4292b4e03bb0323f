package org.fdnet.bench.report;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * One benchmark run as a user runs it: {@code bin/fdnet bench NAME ARGS} in a child process (so it gets the
 * launcher's JVM options, e.g. the logger's), without a rebuild. Its output is echoed, indented, while it runs
 * (the report's progress) and kept for the figures. A benchmark that outlives its time is killed; what it printed
 * until then is still read.
 */
final class BenchmarkProcess {
    /** The run's output and how it ended. */
    record Result(List<String> output, int exitCode, boolean timedOut) {
    }

    private BenchmarkProcess() {
    }

    static Result run(Path launcher, List<String> args, long timeoutSeconds, PrintWriter echo) {
        List<String> command = new ArrayList<>();
        command.add(launcher.toString());
        command.addAll(args);
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        builder.environment().put("FDNET_NO_BUILD", "1");
        Process process;
        try {
            process = builder.start();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot start " + String.join(" ", command), e);
        }
        List<String> output = new ArrayList<>();
        Thread pump = new Thread(() -> copy(process, output, echo), "bench-report-output");
        pump.setDaemon(true);
        pump.start();
        boolean ended;
        try {
            ended = process.waitFor(timeoutSeconds, TimeUnit.SECONDS);
            if (!ended) {
                process.descendants().forEach(ProcessHandle::destroyForcibly);
                process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }
            pump.join(5_000);
        } catch (InterruptedException e) {
            process.descendants().forEach(ProcessHandle::destroyForcibly);
            process.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while " + String.join(" ", args) + " ran", e);
        }
        synchronized (output) {
            return new Result(List.copyOf(output), ended ? process.exitValue() : -1, !ended);
        }
    }

    private static void copy(Process process, List<String> output, PrintWriter echo) {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                synchronized (output) {
                    output.add(line);
                }
                echo.println("    " + line);
                echo.flush();
            }
        } catch (IOException e) {
            echo.println("    (output ended: " + e.getMessage() + ")");
            echo.flush();
        }
    }
}
