package org.fdnet.viewer.ui;

import java.io.IOException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.Consumer;
import java.util.function.IntConsumer;
import javax.swing.SwingUtilities;
import org.fdnet.event.client.ResponsiveThreads;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.source.LoggerConnection;

/**
 * Loads a history off Swing's event thread: the request waits on a thread of its own, so the window keeps
 * painting while the logger answers, and that thread is one a waiting viewer depends on — real-time where
 * permitted ({@link ResponsiveThreads}), like the connection's reader, so the answer is taken in the moment it
 * arrives even while the logger drains a backlog on the same cores. The outcome is handed back on the event thread.
 */
final class HistoryLoader implements AutoCloseable {
    private final ExecutorService thread = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(() -> {
            ResponsiveThreads.raiseCurrent("the viewer's history loader");
            r.run();
        }, "fdnet-history-loader");
        t.setDaemon(true);
        return t;
    });

    /**
     * Fills {@code into} with the sources' values in {@code [from, to]} (µs); then, on the event thread, {@code done}
     * with the number of values, or {@code failed} with why not.
     */
    void load(LoggerConnection connection, int[] sources, long from, long to, PlotData into, IntConsumer done,
              Consumer<IOException> failed) {
        ask(() -> connection.loadHistory(sources, from, to, into), done::accept, failed);
    }

    /** A request to the logger that answers a value. */
    interface Request<T> {
        T ask() throws IOException;
    }

    /** Asks on the loader's thread; then, on the event thread, {@code done} with the answer, or {@code failed}. */
    <T> void ask(Request<T> request, Consumer<T> done, Consumer<IOException> failed) {
        thread.execute(() -> {
            try {
                T answer = request.ask();
                SwingUtilities.invokeLater(() -> done.accept(answer));
            } catch (IOException e) {
                SwingUtilities.invokeLater(() -> failed.accept(e));
            }
        });
    }

    @Override
    public void close() {
        thread.shutdownNow();
    }
}
