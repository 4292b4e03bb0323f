package org.fdnet.bench;

import java.util.List;
import org.fdnet.corba.FdnetChildProcess;

/**
 * One {@code fdnet} command run to its end in a fresh child JVM on this JVM's class path (the project's
 * one way to start a child: {@link FdnetChildProcess}), timed from the spawn to the exit: what a user who
 * types the command pays, JVM start included. The child's output is kept, so a probe can report its own
 * timings from inside.
 *
 * @param output     every line the child printed
 * @param wallMillis from starting the process until it had exited
 */
public record FreshJvmRun(List<String> output, double wallMillis) {
    private static final long TIMEOUT_MILLIS = 300_000;

    /**
     * Runs {@code fdnet ARGS...} and waits for it to exit.
     *
     * @param doneMarker text of the child's last line of interest (it must print it; the run fails otherwise)
     * @throws IllegalStateException with the child's output when it fails, exits non-zero or runs too long
     */
    public static FreshJvmRun of(String label, List<String> fdnetArgs, String doneMarker) {
        long start = System.nanoTime();
        try (FdnetChildProcess child = FdnetChildProcess.start(label, fdnetArgs, doneMarker, TIMEOUT_MILLIS)) {
            int exit = child.awaitExit(TIMEOUT_MILLIS);
            double wall = (System.nanoTime() - start) / 1e6;
            if (exit != 0) {
                throw new IllegalStateException(label + " exited with " + exit + "; output:\n"
                        + String.join("\n", child.output()));
            }
            return new FreshJvmRun(child.output(), wall);
        }
    }

    /** The first line containing {@code marker}. */
    public String line(String marker) {
        return output.stream().filter(l -> l.contains(marker)).findFirst()
                .orElseThrow(() -> new IllegalStateException("no line with '" + marker + "' in:\n" + String.join("\n", output)));
    }
}
