package org.fdnet.event.client;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Puts a thread that a waiting viewer depends on — the logger's sender thread answering it, the viewer's reader
 * thread taking the answer in — in Linux's real-time class ({@code SCHED_FIFO}, priority {@value #PRIORITY}).
 *
 * <p>Why: while the logger drains a backlog its receivers, writer and PostgreSQL backends keep both cores busy.
 * A normal thread woken by a viewer's request then waits until the running thread's time slice ends, which this
 * kernel notices at its next tick (4 ms at 250 Hz) — measured in {@code bench logger}, 2 to 4 ms per wake-up,
 * and a query wakes three threads. A real-time thread runs as soon as it is woken. The work such a thread does
 * is short (an answer from the cache, then it sleeps on its socket again); the kernel keeps 5 % of every second
 * for normal threads whatever real-time threads do.
 *
 * <p>How: the thread's id from {@code /proc/thread-self/stat}, then {@code chrt} (Java has no call for it). It
 * needs root or an {@code RLIMIT_RTPRIO} above 0 ({@code bin/fdnet} runs as the user who starts it): without
 * them the thread stays a normal one at its Java priority; that is said once per process, at info level, and
 * nothing else changes.
 */
public final class ResponsiveThreads {
    /** The lowest real-time priority: above every normal thread, below roq-sim's 1 kHz loop (priority 80). */
    public static final int PRIORITY = 1;
    private static final Logger LOG = LoggerFactory.getLogger(ResponsiveThreads.class);
    private static final long CHRT_TIMEOUT_SECONDS = 5;
    private static final AtomicBoolean REPORTED = new AtomicBoolean();

    private ResponsiveThreads() {
    }

    /**
     * Puts the calling thread in the real-time class; returns whether it is there now. Never throws.
     *
     * @param role what the thread does, for the one message when it cannot be done
     * @return true when the thread now runs under {@code SCHED_FIFO}; false when it stays a normal thread
     */
    public static boolean raiseCurrent(String role) {
        String tid;
        try {
            String stat = Files.readString(Path.of("/proc/thread-self/stat"), StandardCharsets.US_ASCII);
            tid = stat.substring(0, stat.indexOf(' '));
        } catch (IOException | RuntimeException e) {
            return notRaised(role, "no /proc/thread-self (not Linux?): " + e.getMessage());
        }
        try {
            Process p = new ProcessBuilder("chrt", "-f", "-p", Integer.toString(PRIORITY), tid)
                    .redirectErrorStream(true).start();
            if (!p.waitFor(CHRT_TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                return notRaised(role, "chrt did not finish within " + CHRT_TIMEOUT_SECONDS + " s");
            }
            String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
            return p.exitValue() == 0 || notRaised(role, "chrt: " + output);
        } catch (IOException e) {
            return notRaised(role, "cannot run chrt: " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    private static boolean notRaised(String role, String why) {
        if (REPORTED.compareAndSet(false, true)) {
            LOG.info("{} runs as a normal thread, not real-time ({}); real-time needs root or RLIMIT_RTPRIO, and"
                    + " without it a viewer's query can wait a few milliseconds for a busy CPU", role, why);
        } else {
            LOG.debug("{} stays a normal thread: {}", role, why);
        }
        return false;
    }
}
