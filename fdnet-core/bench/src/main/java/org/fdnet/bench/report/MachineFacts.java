package org.fdnet.bench.report;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.util.Locale;

/** The facts a report row carries about the machine and the project: load average, cores, memory, JDK, commit. */
final class MachineFacts {
    private MachineFacts() {
    }

    /** The 1-minute load average ({@code /proc/loadavg}); the system's average where that file is missing. */
    static String loadAverage() {
        try {
            return Files.readString(Path.of("/proc/loadavg")).split(" ")[0];
        } catch (IOException | RuntimeException e) {
            return String.format(Locale.ROOT, "%.2f", ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        }
    }

    static String machine() {
        long bytes = ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean())
                .getTotalMemorySize();
        return String.format(Locale.ROOT, "%d cores, %d GiB, JDK %s", Runtime.getRuntime().availableProcessors(),
                Math.round(bytes / (1024.0 * 1024 * 1024)), System.getProperty("java.version"));
    }

    static String today() {
        return LocalDate.now(ZoneOffset.UTC).toString();
    }

    /** The project's commit, abbreviated, with {@code +changes} when its tracked files (but the report's own) differ. */
    static String commit(Path project) {
        String head = git(project, "rev-parse", "--short", "HEAD");
        if (head.isEmpty()) {
            return "unknown";
        }
        return git(project, "status", "--porcelain", "--untracked-files=no", "--", ".", ":!docs/benchmarks.md").isEmpty()
                ? head : head + "+changes";
    }

    private static String git(Path project, String... args) {
        String[] command = new String[args.length + 3];
        command[0] = "git";
        command[1] = "-C";
        command[2] = project.toString();
        System.arraycopy(args, 0, command, 3, args.length);
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
            return p.waitFor() == 0 ? out : "";
        } catch (IOException e) {
            return "";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "";
        }
    }
}
