package org.fdnet.viewer.ui;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import javax.swing.SwingUtilities;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.EventClock;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.ValueType;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.logger.InProcessLogger;
import org.fdnet.viewer.cli.ViewerCommand;
import org.fdnet.viewer.source.Replay;
import picocli.CommandLine;

/**
 * Run on a real display by {@link ViewerWindowDisplayTest}: a logger, a writer of three Datas, the viewer
 * window opened through its public API (live plot, pause, zoom, history, replay) and {@code fdnet viewer
 * --screenshot}. Prints {@code STEP …} lines; exit 0 when every step passed.
 * Args: SCREENSHOT_OF_WINDOW SCREENSHOT_OF_COMMAND
 */
public final class ViewerScenario {
    private ViewerScenario() {
    }

    public static void main(String[] args) throws Exception {
        try (InProcessLogger logger = InProcessLogger.throwaway()) {
            AtomicBoolean writing = new AtomicBoolean(true);
            LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(), "scenario"));
            EventClock clock = new EventClock();
            String[] names = {"pitch", "roll", "stability margin", "姿勢"}; // the last: a Japanese name, no values
            for (int n = 0; n < names.length; n++) {
                client.accept(new NodeNamedEvent(n, clock.next(), NodeKind.DATA, new NodeRef("Pose", names[n])));
            }
            client.flush(30_000);
            Thread writer = new Thread(() -> {
                long k = 0;
                while (writing.get()) {
                    double t = k++ * 0.005;
                    client.accept(new DataValueEvent(0, clock.next(), ValueType.DOUBLE, Double.toString(0.08 * Math.sin(t * 2.1))));
                    client.accept(new DataValueEvent(1, clock.next(), ValueType.DOUBLE, Double.toString(0.05 * Math.cos(t * 3.3))));
                    client.accept(new DataValueEvent(2, clock.next(), ValueType.DOUBLE,
                            Double.toString(0.04 + 0.015 * Math.sin(t * 0.9) + 0.004 * Math.sin(t * 7))));
                    try {
                        Thread.sleep(5);
                    } catch (InterruptedException e) {
                        return;
                    }
                }
            });
            writer.start();
            ViewerWindow w = ViewerWindow.open(logger.viewerAddress(),
                    List.of("Pose/pitch[rad]", "Pose/roll[rad]", "Pose/stability margin[m]"));
            wait(() -> w.livePlot().data().acceptedEvents() > 100 && w.livePlot().frames() > 5, "live values drawn");
            System.out.println("STEP live values drawn: " + w.livePlot().data().acceptedEvents() + " values, "
                    + w.livePlot().data().series().size() + " series");
            wait(() -> w.namesFont().canDisplayUpTo("Pose/姿勢") == -1 && !w.statusText().contains("cannot be shown"),
                    "the node list's font displays the Japanese name");
            System.out.println("STEP Japanese name legible in " + w.namesFont().getFamily());
            SwingUtilities.invokeAndWait(() -> {
                w.livePlot().setPaused(true);
                w.livePlot().zoom(0.5);
                w.livePlot().setCursorX(600);
            });
            long end = w.livePlot().viewEnd();
            Thread.sleep(300);
            check(w.livePlot().viewEnd() == end, "paused view stays");
            System.out.println("STEP paused and zoomed");
            SwingUtilities.invokeAndWait(() -> w.livePlot().setPaused(false));
            w.screenshot(Path.of(args[0]));
            System.out.println("STEP window screenshot");
            int run = w.connection().runs().get(0).runId();
            SwingUtilities.invokeAndWait(() -> {
                w.chooseReplay(run, 0, 60, "10×");
                w.startReplay();
            });
            Replay r = w.replay();
            check(r != null, "replay started: " + w.statusText());
            check(r.await(60_000), "replay finished");
            check(w.replayPlot().data().acceptedEvents() == r.total(), "replay plotted every value");
            System.out.println("STEP replay " + r.total() + " values");
            SwingUtilities.invokeAndWait(w::dispose);
            int exit = new CommandLine(new ViewerCommand()).execute("--logger", logger.viewerAddress(), "--nodes",
                    "Pose/pitch[rad],Pose/roll[rad],Pose/stability margin[m]", "--window", "5", "--screenshot", args[1],
                    "--after", "3");
            check(exit == 0 && Files.size(Path.of(args[1])) > 10_000, "fdnet viewer --screenshot wrote its PNG");
            System.out.println("STEP command screenshot");
            int bad = new CommandLine(new ViewerCommand()).execute("--logger", logger.viewerAddress(), "--nodes", "Nowhere/nothing");
            check(bad == 2, "an unknown node is refused with exit 2, was " + bad);
            System.out.println("STEP unknown node refused");
            writing.set(false);
            writer.join();
            client.close();
        }
        System.out.println("STEP all passed");
        System.exit(0);
    }

    private interface Condition {
        boolean holds() throws Exception;
    }

    private static void wait(Condition c, String what) throws Exception {
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (!c.holds()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out: " + what);
            }
            Thread.sleep(50);
        }
    }

    private static void check(boolean ok, String what) {
        if (!ok) {
            System.out.println("FAILED " + what);
            System.exit(1);
        }
    }
}
