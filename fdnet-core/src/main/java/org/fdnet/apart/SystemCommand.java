package org.fdnet.apart;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * Runs one of the system tools the rig drives ({@code ip}, {@code nft}, {@code tc}) and returns its output, bounded
 * in time: a tool that fails names itself, its arguments and what it printed.
 */
final class SystemCommand {
    private static final long TIMEOUT_SECONDS = 30;

    /** Where the tools live when {@code PATH} lacks the system folders (e.g. a non-login shell). */
    private static final List<String> SYSTEM_FOLDERS = List.of("/usr/sbin", "/sbin", "/usr/bin", "/bin");

    private SystemCommand() {
    }

    /**
     * The absolute path of tool {@code name}, searched on {@code PATH} and then in the system folders.
     *
     * @throws IllegalStateException naming the Debian packages to install when it is nowhere
     */
    static String tool(String name) {
        List<String> folders = new ArrayList<>();
        String path = System.getenv("PATH");
        if (path != null) {
            folders.addAll(List.of(path.split(File.pathSeparator)));
        }
        folders.addAll(SYSTEM_FOLDERS);
        for (String folder : folders) {
            Path candidate = Path.of(folder, name);
            if (!folder.isEmpty() && Files.isExecutable(candidate)) {
                return candidate.toString();
            }
        }
        throw new IllegalStateException("the apart rig needs the tool '" + name + "', which is not installed:"
                + " apt-get install -y iproute2 nftables");
    }

    /**
     * Runs {@code argv}, optionally feeding {@code input} on its standard input.
     *
     * @return the tool's standard output
     * @throws IllegalStateException when it cannot start, does not finish in time or exits with another code than 0
     */
    static String run(List<String> argv, String input) {
        Result r = attempt(argv, input);
        if (r.exitCode() != 0) {
            throw new IllegalStateException(String.join(" ", argv) + " failed (exit " + r.exitCode() + "): "
                    + r.errors().strip());
        }
        return r.output();
    }

    /** As {@link #run(List, String)} without input. */
    static String run(String... argv) {
        return run(List.of(argv), null);
    }

    /** Runs {@code argv} and returns its exit code and output, whatever the code. */
    static Result attempt(List<String> argv, String input) {
        Process p;
        try {
            p = new ProcessBuilder(argv).start();
        } catch (IOException e) {
            throw new IllegalStateException("cannot run " + argv.get(0) + ": " + e.getMessage(), e);
        }
        CompletableFuture<String> out = CompletableFuture.supplyAsync(() -> readAll(p, false));
        CompletableFuture<String> err = CompletableFuture.supplyAsync(() -> readAll(p, true));
        try {
            if (input != null) {
                p.getOutputStream().write(input.getBytes(StandardCharsets.UTF_8));
            }
            p.getOutputStream().close();
            if (!p.waitFor(TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                throw new IllegalStateException(String.join(" ", argv) + " did not finish in " + TIMEOUT_SECONDS + " s");
            }
            return new Result(p.exitValue(), out.get(5, TimeUnit.SECONDS), err.get(5, TimeUnit.SECONDS));
        } catch (IOException | ExecutionException | TimeoutException e) {
            p.destroyForcibly();
            throw new IllegalStateException(String.join(" ", argv) + " failed: " + e.getMessage(), e);
        } catch (InterruptedException e) {
            p.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new IllegalStateException(String.join(" ", argv) + " was interrupted", e);
        }
    }

    private static String readAll(Process p, boolean errors) {
        try {
            return new String((errors ? p.getErrorStream() : p.getInputStream()).readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            return "";
        }
    }

    /** What a tool printed and how it ended. */
    record Result(int exitCode, String output, String errors) {
    }
}
