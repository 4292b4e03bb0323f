package org.fdnet.viewer.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import javax.swing.SwingUtilities;
import org.fdnet.logger.InProcessLogger;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.source.LoggerConnection;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** A history is fetched off the event thread and its outcome — values or the failure — handed back on it. */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class HistoryLoaderTest {
    @Test
    void shouldHandTheOutcomeBackOnTheEventThreadAndAFailureToo() throws Exception {
        try (InProcessLogger logger = InProcessLogger.throwaway();
             HistoryLoader loader = new HistoryLoader()) {
            LoggerConnection connection = new LoggerConnection(logger.viewerAddress(), new PlotData());
            CompletableFuture<String> loaded = new CompletableFuture<>();
            loader.load(connection, new int[0], 0, Long.MAX_VALUE, new PlotData(),
                    n -> loaded.complete(n + " values, on the event thread: " + SwingUtilities.isEventDispatchThread()),
                    e -> loaded.complete("failed: " + e.getMessage()));
            assertThat(loaded.get(30, TimeUnit.SECONDS)).isEqualTo("0 values, on the event thread: true");

            connection.close();
            CompletableFuture<String> failed = new CompletableFuture<>();
            loader.load(connection, new int[0], 0, Long.MAX_VALUE, new PlotData(), n -> failed.complete("loaded " + n),
                    e -> failed.complete(e.getClass().getSimpleName() + " on the event thread: "
                            + SwingUtilities.isEventDispatchThread()));
            assertThat(failed.get(30, TimeUnit.SECONDS)).isEqualTo(IOException.class.getSimpleName()
                    + " on the event thread: true");
        }
    }
}
