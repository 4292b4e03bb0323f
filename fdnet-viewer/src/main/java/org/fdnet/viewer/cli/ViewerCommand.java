package org.fdnet.viewer.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import javax.swing.SwingUtilities;
import org.fdnet.viewer.layout.LayoutFile;
import org.fdnet.viewer.layout.ViewerLayout;
import org.fdnet.viewer.source.Replay;
import org.fdnet.viewer.ui.ViewerWindow;
import org.fdnet.tls.TlsOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code fdnet viewer}: the Network State Viewer on a logger's viewer service. */
@Command(name = "viewer", mixinStandardHelpOptions = true,
        description = {"The Network State Viewer: plots of Data values on one linked time axis,",
            "live through the logger's monitor stream, a history of a time range, or the",
            "replay of a recorded run at 1x, 2x or 10x. Layouts are saved and reopened",
            "(--layout FILE); CSV export. A RoQ run opens with its ready layout."})
public final class ViewerCommand implements Callable<Integer> {
    @Option(names = "--logger", defaultValue = "127.0.0.1:5556", paramLabel = "HOST:PORT",
            description = "the logger's viewer (sender) service (default ${DEFAULT-VALUE})")
    String logger;

    @Option(names = "--nodes", split = ",", paramLabel = "NODE",
            description = "Datas to plot live, one plot per unit: Module/Node or Node, optionally with a unit,"
                    + " e.g. 'Balance/margin[m]'")
    List<String> nodes = new ArrayList<>();

    @Option(names = "--layout", paramLabel = "FILE",
            description = "plots and their series from a layout file (the window's Save layout… writes one)")
    Path layout;

    @Option(names = "--window", defaultValue = "10",
            description = "seconds of the time window (default ${DEFAULT-VALUE}; a layout file gives its own)")
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
            ViewerLayout chosen = layout == null ? null : LayoutFile.read(layout);
            window = ViewerWindow.open(logger, nodes, chosen);
        } catch (IllegalArgumentException e) {
            System.err.println("fdnet viewer: " + e.getMessage());
            return 2;
        } catch (java.nio.file.NoSuchFileException e) {
            System.err.println("fdnet viewer: --layout " + e.getFile() + ": no such file");
            return 2;
        } catch (IOException e) {
            System.err.println("fdnet viewer: " + e.getMessage());
            return 1;
        }
        System.out.printf("viewer on the logger at %s: plotting %d node(s) live in %d plot(s)%n", logger, nodes.size(),
                window.plots().plots().size());
        if (layout == null) {
            SwingUtilities.invokeAndWait(() -> window.plots().axis().setWindowMicros((long) (windowSeconds * 1e6)));
        }
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
                    window.liveData().acceptedEvents(), window.plots().framesPainted(),
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
