package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/** A thread on the network's path is put under SCHED_FIFO just below the loop when the system allows; only it. */
class RealTimeThreadsTest {
    @Test
    void shouldPutTheCallingThreadAloneUnderSchedFifoJustBelowTheLoopAsRoot() throws Exception {
        AtomicReference<ThreadScheduling> before = new AtomicReference<>();
        AtomicReference<ThreadScheduling> after = new AtomicReference<>();
        boolean[] promoted = new boolean[1];
        Exception[] failure = new Exception[1];
        Thread t = new Thread(() -> {
            try {
                before.set(ThreadScheduling.ofCurrentThread());
                promoted[0] = RealTimeThreads.promoteCurrentThread();
                after.set(ThreadScheduling.ofCurrentThread());
            } catch (Exception e) {
                failure[0] = e;
            }
        }, "promoted");
        t.start();
        t.join();
        assertThat(failure[0]).isNull();
        assertThat(before.get().fifo()).as("an ordinary thread before").isFalse();
        assertThat(promoted[0]).as("promoted, as root").isEqualTo(ThreadScheduling.runningAsRoot());
        if (promoted[0]) {
            assertThat(after.get()).isEqualTo(new ThreadScheduling(ThreadScheduling.SCHED_FIFO,
                    SimOptions.DEFAULT_PRIORITY - 1));
        } else {
            assertThat(after.get()).as("refused: the thread runs on as it was").isEqualTo(before.get());
        }
        assertThat(ThreadScheduling.ofCurrentThread().fifo()).as("the caller's thread only").isFalse();
    }
}
