package org.fdnet.event.client;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/**
 * A thread that asks becomes real-time (SCHED_FIFO 1) where the process may have it (root here, as in CI), and
 * only that thread; where it may not, the call says so and the thread stays a normal one.
 */
class ResponsiveThreadsTest {
    private static final int SCHED_OTHER = 0;
    private static final int SCHED_FIFO = 1;

    @Test
    void shouldMakeOnlyTheCallingThreadRealTimeWherePermitted() throws Exception {
        AtomicReference<int[]> seen = new AtomicReference<>();
        AtomicReference<Boolean> raised = new AtomicReference<>();
        Thread t = new Thread(() -> {
            raised.set(ResponsiveThreads.raiseCurrent("a test thread"));
            try {
                seen.set(policyAndPriority("thread-self"));
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        }, "responsive-test");
        t.start();
        t.join(10_000);

        boolean root = isRoot();
        assertThat(raised.get()).as("raised (running as root: %s)", root).isEqualTo(root);
        assertThat(seen.get()).containsExactly(root ? SCHED_FIFO : SCHED_OTHER, root ? ResponsiveThreads.PRIORITY : 0);
        assertThat(policyAndPriority("thread-self")).as("the test's own thread").containsExactly(SCHED_OTHER, 0);
    }

    /** Fields 41 (policy) and 40 (rt_priority) of /proc/.../stat. */
    private static int[] policyAndPriority(String which) throws IOException {
        String stat = Files.readString(Path.of("/proc/" + which + "/stat"));
        String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
        return new int[] {Integer.parseInt(f[41 - 3]), Integer.parseInt(f[40 - 3])};
    }

    private static boolean isRoot() throws IOException {
        for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
            if (line.startsWith("Uid:")) {
                return line.split("\\s+")[2].equals("0"); // the effective user id
            }
        }
        throw new IllegalStateException("no Uid: line in /proc/self/status");
    }
}
