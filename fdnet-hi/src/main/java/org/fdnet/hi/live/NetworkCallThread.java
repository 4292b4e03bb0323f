package org.fdnet.hi.live;

import java.awt.SecondaryLoop;
import java.awt.Toolkit;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.Supplier;
import javax.swing.SwingUtilities;

/**
 * The one thread a {@link LiveSession} calls its network on: a change sent to a network in another process may take
 * up to the ORB's call timeout (10 s), and the Swing thread must not wait on it.
 *
 * <pre>
 *   Swing thread: edit / command ─▶ call(work) ─submit─▶ sender thread: work (network.apply, load, send …)
 *        │ keeps dispatching events (repaints, status bar "Sending …") in a secondary loop   │
 *        ◀──────────────────── result (the loop is left once it is there) ◀─────────────────┘
 * </pre>
 *
 * The caller gets the outcome as from a direct call, so the view changes only once the network executed the change.
 * One call at a time: a call started from an event dispatched meanwhile (a second edit while one is under way) is
 * answered {@code null} at once, and the caller refuses it.
 */
final class NetworkCallThread implements AutoCloseable {
    private final ExecutorService sender;
    private boolean busy;

    NetworkCallThread(String networkName) {
        this.sender = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "fdnet-hi-send-" + networkName);
            t.setDaemon(true);
            return t;
        });
    }

    /** A call is under way (Swing thread). */
    boolean busy() {
        return busy;
    }

    /**
     * Runs {@code work} on the sender thread and answers its result (its exception is thrown here); on the Swing
     * thread the events keep being dispatched meanwhile. {@code null} when a call is already under way.
     */
    <T> T call(Supplier<T> work) {
        if (!SwingUtilities.isEventDispatchThread()) {
            return await(sender.submit(work::get));
        }
        if (busy) {
            return null;
        }
        busy = true;
        try {
            SecondaryLoop loop = Toolkit.getDefaultToolkit().getSystemEventQueue().createSecondaryLoop();
            Future<T> result = sender.submit(() -> {
                try {
                    return work.get();
                } finally {
                    // queued behind whatever is pending, so it is dispatched inside the loop even when the work
                    // ends before the loop is entered
                    SwingUtilities.invokeLater(loop::exit);
                }
            });
            loop.enter();
            return await(result);
        } finally {
            busy = false;
        }
    }

    private static <T> T await(Future<T> result) {
        try {
            return result.get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof RuntimeException r) {
                throw r;
            }
            if (e.getCause() instanceof Error err) {
                throw err;
            }
            throw new IllegalStateException(e.getCause());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for the network", e);
        }
    }

    @Override
    public void close() {
        sender.shutdown();
    }
}
