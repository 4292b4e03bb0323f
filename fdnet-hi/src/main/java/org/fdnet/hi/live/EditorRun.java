package org.fdnet.hi.live;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.fdnet.control.LiveNetwork;
import org.fdnet.run.NetworkRun;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A network run started from the editor (Live → Run): the same {@link NetworkRun} as {@code fdnet run}, in a
 * thread of the editor's process — on this machine, over the hosts its nodes name, or on the simulated RoQ. What
 * it prints (placement, summary, what the logger committed) is kept and logged. {@link #stop} ends it: every
 * host's part, the run's events committed.
 */
public final class EditorRun {
    private static final Logger LOG = LoggerFactory.getLogger(EditorRun.class);

    private final NetworkRun run;
    private final StringWriter text = new StringWriter();
    private final Thread thread;
    private volatile int exit = -1;
    private LiveNetwork live;

    private EditorRun(Path file, RunChoice choice) {
        PrintWriter out = new PrintWriter(text, true);
        this.run = new NetworkRun(file, choice.options(), out, out, null);
        this.thread = new Thread(() -> {
            try {
                exit = run.run();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } catch (RuntimeException e) {
                LOG.error("the run of {} failed", file, e);
                out.println("the run failed: " + e);
            }
            LOG.info("the run of {} ended (exit {}):\n{}", file, exit, text);
        }, "fdnet-hi-run");
        thread.setDaemon(true);
    }

    /**
     * Starts {@code file} where {@code choice} says and waits (at most {@code timeoutMillis}) until it runs.
     *
     * @throws IllegalStateException with what the run said when it did not start
     */
    public static EditorRun start(Path file, RunChoice choice, long timeoutMillis) throws InterruptedException {
        EditorRun r = new EditorRun(file, choice);
        r.thread.start();
        r.live = r.run.awaitRunning(timeoutMillis, TimeUnit.MILLISECONDS);
        if (r.live == null) {
            r.stop();
            String said = r.output().strip();
            throw new IllegalStateException(said.isEmpty() ? "it did not start within " + timeoutMillis + " ms"
                    : said.substring(said.lastIndexOf('\n') + 1));
        }
        return r;
    }

    /** The running network, to attach the editor to. */
    public LiveNetwork live() {
        return live;
    }

    /** Ends the run everywhere and waits (at most a minute) for it to commit and stop; its exit code. */
    public int stop() throws InterruptedException {
        run.stop();
        thread.join(60_000);
        return exit;
    }

    /** Everything the run printed so far. */
    public String output() {
        return text.toString();
    }
}
