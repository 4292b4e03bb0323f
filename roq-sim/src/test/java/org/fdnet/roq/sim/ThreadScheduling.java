package org.fdnet.roq.sim;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

/** A thread's scheduling policy and real-time priority as Linux reports them ({@code /proc/.../stat}), for tests. */
public record ThreadScheduling(int policy, int priority) {
    /** {@code SCHED_FIFO} in {@code sched.h}. */
    public static final int SCHED_FIFO = 1;

    /** The calling thread's. */
    public static ThreadScheduling ofCurrentThread() throws IOException {
        return of(Path.of("/proc/thread-self/stat"));
    }

    /** The thread of this process whose name (as the kernel holds it, 15 characters at most) is {@code name}. */
    public static ThreadScheduling ofThreadNamed(String name) throws IOException {
        try (Stream<Path> tasks = Files.list(Path.of("/proc/self/task"))) {
            for (Path task : (Iterable<Path>) tasks::iterator) {
                if (Files.readString(task.resolve("comm")).strip().equals(name)) {
                    return of(task.resolve("stat"));
                }
            }
        }
        throw new IOException("no thread named '" + name + "' in /proc/self/task");
    }

    private static ThreadScheduling of(Path stat) throws IOException {
        String text = Files.readString(stat);
        // fields after the name's closing parenthesis start at field 3; rt_priority is field 40, policy field 41
        String[] f = text.substring(text.lastIndexOf(')') + 2).trim().split("\\s+");
        return new ThreadScheduling(Integer.parseInt(f[41 - 3]), Integer.parseInt(f[40 - 3]));
    }

    /** The effective uid from /proc/self/status is 0 (Linux; roq-sim is Linux-only). */
    public static boolean runningAsRoot() throws IOException {
        for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
            if (line.startsWith("Uid:")) {
                return line.split("\\s+")[2].equals("0");
            }
        }
        throw new IOException("/proc/self/status has no Uid line");
    }

    public boolean fifo() {
        return policy == SCHED_FIFO;
    }
}
