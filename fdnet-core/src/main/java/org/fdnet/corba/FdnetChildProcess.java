package org.fdnet.corba;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * An {@code fdnet} command running in a child JVM on this machine's class path: how the benchmark and the
 * multi-process tests start naming services and hosts. Its output is kept (for failure messages) and
 * {@link #start} returns once a line containing the ready marker appears. {@link #close()} always ends
 * the process: a polite destroy first, then {@code destroyForcibly}.
 */
public final class FdnetChildProcess implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(FdnetChildProcess.class);

    private final String label;
    private final Process process;
    private final List<String> output = new ArrayList<>();
    private boolean ready;
    /** The child's output has ended (it exited, or closed it): no ready marker can come any more. */
    private boolean outputEnded;
    private Thread reader;

    private FdnetChildProcess(String label, Process process) {
        this.label = label;
        this.process = process;
    }

    /**
     * Starts {@code fdnet ARGS...} and waits until it prints a line containing {@code readyMarker}.
     *
     * @throws IllegalStateException with the child's output when it exits or is not ready in time
     */
    public static FdnetChildProcess start(String label, List<String> fdnetArgs, String readyMarker, long timeoutMillis) {
        return start(label, List.of(), fdnetArgs, readyMarker, timeoutMillis);
    }

    /** As above, the JVM started with {@code jvmOptions} too (e.g. {@code -Duser.home=DIR} for a home of its own). */
    public static FdnetChildProcess start(String label, List<String> jvmOptions, List<String> fdnetArgs,
                                          String readyMarker, long timeoutMillis) {
        return start(label, List.of(), jvmOptions, fdnetArgs, readyMarker, timeoutMillis);
    }

    /**
     * As above, the JVM started through {@code launchPrefix}: e.g. {@code ip netns exec NS} from
     * {@code ApartRig.command(host, List.of())}, to run it on a host of the apart rig. The prefix must exec the JVM
     * (keep its process id), so that stopping and killing reach it.
     */
    public static FdnetChildProcess start(String label, List<String> launchPrefix, List<String> jvmOptions,
                                          List<String> fdnetArgs, String readyMarker, long timeoutMillis) {
        List<String> command = new ArrayList<>(launchPrefix);
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.add("-Xss1m");
        if (QuickJitCommands.matches(fdnetArgs)) {
            command.add(QuickJitCommands.OPTION);
        }
        command.addAll(jvmOptions);
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add("org.fdnet.cli.FdnetCommand");
        command.addAll(fdnetArgs);
        Process p;
        try {
            p = new ProcessBuilder(command).redirectErrorStream(true).start();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot start " + label, e);
        }
        FdnetChildProcess child = new FdnetChildProcess(label, p);
        Thread reader = new Thread(() -> child.pump(readyMarker), "fdnet-child-" + label);
        reader.setDaemon(true);
        child.reader = reader;
        reader.start();
        if (!child.awaitReady(timeoutMillis)) {
            child.close();
            throw new IllegalStateException(label + " did not become ready in " + timeoutMillis + " ms; output:\n"
                    + String.join("\n", child.output()));
        }
        return child;
    }

    private void pump(String readyMarker) {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                synchronized (this) {
                    output.add(line);
                    if (line.contains(readyMarker)) {
                        ready = true;
                    }
                    notifyAll();
                }
            }
        } catch (IOException e) {
            LOG.debug("{} output closed: {}", label, e.toString());
        }
        synchronized (this) {
            outputEnded = true;
            notifyAll();
        }
    }

    private synchronized boolean awaitReady(long timeoutMillis) {
        long deadline = System.currentTimeMillis() + timeoutMillis;
        // Until the output has ended, not until the process has: a child that prints its marker and exits
        // at once must still be seen as ready once its last lines are read.
        while (!ready && !outputEnded) {
            long left = deadline - System.currentTimeMillis();
            if (left <= 0) {
                return false;
            }
            try {
                wait(Math.min(left, 100));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return false;
            }
        }
        return ready;
    }

    /** Writes {@code line} to the process's standard input (e.g. a command for {@code fdnet run}). */
    public void send(String line) {
        try {
            process.getOutputStream().write((line + System.lineSeparator()).getBytes(StandardCharsets.UTF_8));
            process.getOutputStream().flush();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write to " + label + "'s standard input", e);
        }
    }

    public synchronized List<String> output() {
        return List.copyOf(output);
    }

    /** Waits for the process to end by itself; returns its exit code, or -1 if it is still running. */
    public int awaitExit(long timeoutMillis) {
        try {
            if (process.waitFor(timeoutMillis, TimeUnit.MILLISECONDS)) {
                reader.join(5_000); // read the output to its end
                return process.exitValue();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return -1;
    }

    public boolean isAlive() {
        return process.isAlive();
    }

    public long pid() {
        return process.pid();
    }

    /** Kills the process at once (SIGKILL, like {@code kill -9}): no shutdown hook runs. */
    public void kill() {
        process.destroyForcibly();
        try {
            process.waitFor(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void close() {
        stop(5_000);
    }

    /**
     * Asks the process to stop (SIGTERM: its shutdown hooks run) and gives it {@code politeMillis} to do so
     * before ending it forcibly; returns once it is gone and its output has been read to the end.
     */
    public void stop(long politeMillis) {
        if (!process.isAlive()) {
            return;
        }
        // Through the handle: Process.destroy() also closes our end of its output, and the lines a shutdown
        // hook prints would be lost.
        process.toHandle().destroy();
        try {
            if (!process.waitFor(politeMillis, TimeUnit.MILLISECONDS)) {
                process.destroyForcibly();
                process.waitFor(5, TimeUnit.SECONDS);
            }
            reader.join(5_000); // the output's last lines (a shutdown hook's report) are read after the exit
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
        }
    }

    /** A port on 127.0.0.1 that was free a moment ago. */
    public static int freePort() {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException("no free port on 127.0.0.1", e);
        }
    }
}
