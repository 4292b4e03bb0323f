package org.fdnet.viewer.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import javax.swing.SwingUtilities;
import org.fdnet.viewer.source.Replay;
import org.fdnet.viewer.ui.ViewerWindow;
import org.fdnet.tls.TlsOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code fdnet viewer}: the Network State Viewer on a logger's viewer service. */
@Command(name = "viewer", mixinStandardHelpOptions = true,
        description = {"The Network State Viewer: live plots of Data values through the logger's monitor stream,",
            "history of a time range, CSV export, and replay of a recorded run at 1x, 2x or 10x."})
public final class ViewerCommand implements Callable<Integer> {
    @Option(names = "--logger", defaultValue = "127.0.0.1:5556", paramLabel = "HOST:PORT",
            description = "the logger's viewer (sender) service (default ${DEFAULT-VALUE})")
    String logger;

    @Option(names = "--nodes", split = ",", paramLabel = "NODE",
            description = "Datas to plot live: Module/Node or Node, optionally with a unit, e.g. 'Balance/margin[m]'")
    List<String> nodes = new ArrayList<>();

    @Option(names = "--window", defaultValue = "10", description = "seconds of the live time window (default ${DEFAULT-VALUE})")
    double windowSeconds;

    @Option(names = "--replay", paramLabel = "RUN_ID", description = "replay this run (its id from the run list) at start")
    Integer replayRun;

    @Option(names = "--from", defaultValue = "0",
            description = "replay from this many seconds after the run's first value; negative: before its last (-60 = the last minute)")
    double from;

    @Option(names = "--to", defaultValue = "60", description = "replay up to this many seconds after the run's first value")
    double to;

    @Option(names = "--speed", defaultValue = "1×", description = "replay speed: 1×, 2× or 10× (1x, 2x, 10x accepted)")
    String speed;

    @Option(names = "--screenshot", paramLabel = "FILE", description = "write a PNG of the window after --after seconds, then exit")
    Path screenshot;

    @Mixin
    TlsOptions tls;

    @Option(names = "--after", defaultValue = "4", description = "seconds to wait before --screenshot (default ${DEFAULT-VALUE})")
    double after;

    @Override
    public Integer call() throws Exception {
        String speedLabel = speed.replace('x', '×').replace('X', '×');
        if (!List.of("1×", "2×", "10×").contains(speedLabel)) {
            System.err.println("--speed " + speed + ": choose 1×, 2× or 10×");
            return 2;
        }
        ViewerWindow window;
        try {
            tls.apply();
            window = ViewerWindow.open(logger, nodes);
        } catch (IllegalArgumentException e) {
            System.err.println("fdnet viewer: " + e.getMessage());
            return 2;
        } catch (IOException e) {
            System.err.println("fdnet viewer: " + e.getMessage());
            return 1;
        }
        System.out.printf("viewer on the logger at %s: plotting %d node(s)%n", logger, nodes.size());
        SwingUtilities.invokeAndWait(() -> window.livePlot().setWindowMicros((long) (windowSeconds * 1e6)));
        if (replayRun != null) {
            SwingUtilities.invokeAndWait(() -> {
                window.chooseReplay(replayRun, from, to, speedLabel);
                window.startReplay();
            });
            System.out.println(window.statusText());
        }
        if (screenshot != null) {
            Thread.sleep((long) (after * 1000));
            window.screenshot(screenshot);
            Replay r = window.replay();
            System.out.printf("screenshot written to %s (live: %,d values, %d frames painted%s)%n", screenshot,
                    window.livePlot().data().acceptedEvents(), window.livePlot().frames(),
                    r == null ? "" : String.format("; replay: %,d of %,d values", r.delivered(), r.total()));
            SwingUtilities.invokeAndWait(window::dispose);
            return 0;
        }
        CountDownLatch closed = new CountDownLatch(1);
        window.addWindowListener(new java.awt.event.WindowAdapter() {
            @Override
            public void windowClosed(java.awt.event.WindowEvent e) {
                closed.countDown();
            }
        });
        closed.await();
        return 0;
    }
}
