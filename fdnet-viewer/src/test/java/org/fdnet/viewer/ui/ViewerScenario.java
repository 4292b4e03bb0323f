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
import org.fdnet.testing.OnEdt;
import org.fdnet.testing.WindowVisibility;
import org.fdnet.viewer.data.NodeSelection;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.layout.LayoutFile;
import org.fdnet.viewer.source.LoggerConnection;
import org.fdnet.viewer.source.Replay;
import picocli.CommandLine;

/**
 * Run on a real display by {@link ViewerWindowDisplayTest}: a logger, a writer of three Datas and a recorded
 * RoQ-like run; the viewer window opened through its public API: one live plot per unit, every control visible,
 * pause, zoom and cursor linked across plots, a series in another unit refused, a series added to a new plot, the
 * layout saved, a replay, the layout reopened from its file, the RoQ run opening with its ready layout; and
 * {@code fdnet viewer --screenshot}. Prints {@code STEP …} lines; exit 0 when every step passed.
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
            int roqRun = recordRoqRun(logger);
            ViewerWindow w = ViewerWindow.open(logger.viewerAddress(),
                    List.of("Pose/pitch[rad]", "Pose/roll[rad]", "Pose/stability margin[m]"));
            wait(() -> w.liveData().acceptedEvents() > 100 && w.plots().framesPainted() > 5, "live values drawn");
            System.out.println("STEP live values drawn: " + w.liveData().acceptedEvents() + " values, "
                    + w.liveData().series().size() + " series");
            check(onEdt(() -> titlesAndUnits(w)).equals("Pose/pitch, Pose/roll·rad|Pose/stability margin·m"), "one live plot per unit: "
                    + onEdt(() -> titlesAndUnits(w)));
            System.out.println("STEP one plot per unit: " + onEdt(() -> titlesAndUnits(w)));
            wait(() -> w.namesFont().canDisplayUpTo("Pose/姿勢") == -1 && !w.statusText().contains("cannot be shown"),
                    "the node tree's font displays the Japanese name");
            System.out.println("STEP Japanese name legible in " + w.namesFont().getFamily());
            List<String> problems = WindowVisibility.problems(w);
            check(problems.isEmpty(), "every control visible at " + w.getWidth() + "x" + w.getHeight() + ": " + problems);
            System.out.println("STEP every control visible at " + w.getWidth() + "x" + w.getHeight());
            SwingUtilities.invokeAndWait(() -> {
                PlotPanel first = w.plots().plots().get(0).plot();
                first.setPaused(true);
                first.zoom(0.5);
                first.setCursorX(300);
            });
            PlotPanel second = w.plots().plots().get(1).plot();
            long end = second.viewEnd();
            Thread.sleep(300);
            check(second.viewEnd() == end && second.paused(), "pausing one plot pauses the other, which stays");
            check(second.windowMicros() == 5_000_000, "zooming one plot zooms the other: " + second.windowMicros());
            check(w.plots().axis().cursor() != TimeAxis.NO_CURSOR, "the cursor of one plot is the cursor of all");
            System.out.println("STEP paused, zoomed and cursor linked");
            PlotView margin = onEdt(() -> w.plots().plots().get(1));
            int refused = onEdt(() -> w.plots().addSeries(w.plots().plots().get(0),
                    List.of(NodeSelection.parse("Pose/stability margin[m]"))));
            check(refused == 0 && w.statusText().contains("'Pose/stability margin' is in m, the plot 'Pose/pitch, Pose/roll' in rad"),
                    "a series in m refused by a plot in rad: " + w.statusText());
            System.out.println("STEP mixed units refused: " + w.statusText());
            int scenarioRun = w.connection().runs().stream().filter(i -> i.runId() != roqRun).findFirst().orElseThrow().runId();
            SwingUtilities.invokeAndWait(() -> w.chooseReplay(scenarioRun, 0, 60, "10×")); // its Datas in the tree
            check(onEdt(() -> w.tree().choose(List.of("Pose/stability margin"))) == 1, "the margin chosen in the tree");
            SwingUtilities.invokeAndWait(() -> click(w, "addToNewPlot"));
            PlotView added = onEdt(() -> w.plots().plots().get(2));
            check(onEdt(added::unit).equals("m") && w.plots().plots().size() == 3, "a series added to a new plot takes its"
                    + " unit: " + onEdt(() -> titlesAndUnits(w)));
            wait(() -> onEdt(() -> added.plot().shownSeries().size()) == 1, "the new plot draws the series");
            System.out.println("STEP series added to a new plot in " + onEdt(added::unit));
            PlotView dropped = onEdt(() -> w.plots().addAfter(added, "dropped"));
            boolean took = onEdt(() -> {
                java.awt.datatransfer.Clipboard drag = new java.awt.datatransfer.Clipboard("drag");
                w.tree().choose(List.of("Pose/pitch"));
                w.tree().getTransferHandler().exportToClipboard(w.tree(), drag, javax.swing.TransferHandler.COPY);
                return dropped.getTransferHandler().importData(new javax.swing.TransferHandler.TransferSupport(dropped,
                        drag.getContents(null)));
            });
            check(took && onEdt(dropped::unit).equals("rad") && onEdt(dropped::entries).size() == 1,
                    "a Data dragged from the tree into an empty plot: " + onEdt(() -> titlesAndUnits(w)));
            System.out.println("STEP dragged into a plot: " + onEdt(dropped::entries));
            SwingUtilities.invokeAndWait(() -> w.plots().removePlot(dropped));
            SwingUtilities.invokeAndWait(() -> w.plots().removePlot(margin));
            check(w.plots().plots().size() == 2, "two plots removed");
            SwingUtilities.invokeAndWait(() -> w.plots().plots().get(0).plot().setPaused(false));
            w.screenshot(Path.of(args[0]));
            System.out.println("STEP window screenshot");
            Path layout = Path.of(args[0]).resolveSibling("saved.layout");
            SwingUtilities.invokeAndWait(() -> w.saveLayout(layout));
            String saved = onEdt(() -> titlesAndUnits(w));
            SwingUtilities.invokeAndWait(() -> {
                w.chooseReplay(scenarioRun, 0, 60, "10×");
                w.startReplay();
            });
            Replay r = w.replay();
            check(r != null, "replay started: " + w.statusText());
            check(r.await(60_000), "replay finished");
            check(w.replayData().acceptedEvents() == r.total(), "replay plotted every value");
            check(onEdt(() -> titlesAndUnits(w)).equals(saved), "a replay keeps the plots chosen");
            Path csv = layout.resolveSibling("replay.csv");
            SwingUtilities.invokeAndWait(() -> w.plots().axis().showRange(w.replayData().firstTime(), w.replayData().lastTime()));
            long rows = onEdt(() -> w.exportCsv(csv));
            List<String> lines = Files.readAllLines(csv);
            check(rows > 100 && lines.size() == rows + 1 && lines.get(0).equals("series,unit,time_us,value")
                    && lines.stream().anyMatch(l -> l.startsWith("Pose/pitch,rad,"))
                    && lines.stream().anyMatch(l -> l.startsWith("Pose/stability margin,m,")),
                    "CSV export of the plotted series: " + rows + " rows, " + (lines.isEmpty() ? "" : lines.get(0)));
            System.out.println("STEP CSV export: " + rows + " rows");
            System.out.println("STEP replay " + r.total() + " values");
            SwingUtilities.invokeAndWait(w::dispose);

            ViewerWindow reopened = ViewerWindow.open(logger.viewerAddress(), List.of(), LayoutFile.read(layout));
            check(onEdt(() -> titlesAndUnits(reopened)).equals(saved), "the layout reopens from its file: "
                    + onEdt(() -> titlesAndUnits(reopened)) + " vs " + saved);
            System.out.println("STEP layout reopened: " + saved);
            SwingUtilities.invokeAndWait(reopened::dispose);

            ViewerWindow roq = ViewerWindow.open(logger.viewerAddress(), List.of());
            SwingUtilities.invokeAndWait(() -> {
                roq.chooseReplay(roqRun, 0, 60, "10×");
                roq.startReplay();
            });
            check(roq.replay() != null && roq.replay().await(60_000), "RoQ run replayed: " + roq.statusText());
            String roqPlots = onEdt(() -> titlesAndUnits(roq));
            check(roqPlots.equals("Attitude (roll, pitch)·rad|Sole forces (one per foot)·N|Stability margin·m"
                    + "|Gait phase (leg swinging, foot in the air)·|Course track (x, y from the start)·m"),
                    "a RoQ run opens with its ready layout: " + roqPlots);
            check(onEdt(() -> roq.plots().plots().get(1).plot().shownSeries().size()) == 4
                    && onEdt(() -> roq.plots().plots().get(1).plot().shownSeries().get(0).unit()).equals("N"),
                    "four sole forces in N");
            check(onEdt(() -> roq.plots().plots().get(4).plot().shownSeries().size()) == 2, "the track's x and y only");
            check(roq.liveData().trackedSources().length == 0, "the ready layout's Datas are replayed, not monitored live");
            check(onEdt(() -> roq.plots().plots().stream().map(v -> v.plot().viewEnd()).distinct().count()) == 1,
                    "every plot of a frame ends at the same instant");
            List<String> roqProblems = WindowVisibility.problems(roq);
            check(roqProblems.isEmpty(), "every control of the RoQ layout visible: " + roqProblems);
            SwingUtilities.invokeAndWait(() -> roq.plots().plots().get(1).plot().setCursorX(560));
            roq.screenshot(Path.of(args[0]).resolveSibling("viewer-roq.png"));
            SwingUtilities.invokeAndWait(() -> roq.plots().setLegendVisible(false));
            check(onEdt(() -> roq.plots().plots().stream().noneMatch(v -> v.plot().legendVisible())), "every legend hidden");
            roq.screenshot(Path.of(args[0]).resolveSibling("viewer-roq-no-legend.png"));
            System.out.println("STEP RoQ layout: " + roqPlots);
            SwingUtilities.invokeAndWait(roq::dispose);
            int exit = new CommandLine(new ViewerCommand()).execute("--logger", logger.viewerAddress(), "--nodes",
                    "Pose/pitch[rad],Pose/roll[rad],Pose/stability margin[m]", "--window", "5", "--screenshot", args[1],
                    "--after", "3");
            int withLayout = new CommandLine(new ViewerCommand()).execute("--logger", logger.viewerAddress(), "--layout",
                    layout.toString(), "--screenshot", Path.of(args[1]).resolveSibling("layout.png").toString(), "--after", "1");
            check(withLayout == 0, "fdnet viewer --layout FILE opens, was " + withLayout);
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

    /** A fake RoQ run: the Datas the ready layout names, with vectors, over two seconds; answers its run id. */
    private static int recordRoqRun(InProcessLogger logger) throws Exception {
        try (LoggerClient roq = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(), "roq"))) {
            EventClock clock = new EventClock();
            String[][] nodes = {{"main", "attitude"}, {"main", "foot forces"}, {"Balance", "margin"}, {"main", "gait phase"},
                {"Course", "track"}, {"main", "joint angles"}};
            for (int n = 0; n < nodes.length; n++) {
                roq.accept(new NodeNamedEvent(n, clock.next(), NodeKind.DATA, new NodeRef(nodes[n][0], nodes[n][1])));
            }
            for (int k = 0; k < 200; k++) {
                double t = k * 0.01;
                roq.accept(new DataValueEvent(0, clock.next(), ValueType.DOUBLES, 0.02 * Math.sin(t) + " " + 0.01 * Math.cos(t)));
                roq.accept(new DataValueEvent(1, clock.next(), ValueType.DOUBLES, "20 21 " + (k % 50 < 25 ? 0 : 25) + " 19"));
                roq.accept(new DataValueEvent(2, clock.next(), ValueType.DOUBLE, Double.toString(0.05 + 0.01 * Math.sin(t))));
                roq.accept(new DataValueEvent(3, clock.next(), ValueType.DOUBLES, (k / 50) % 4 + " " + (k % 50 < 25 ? 0 : 1) + " 0"));
                roq.accept(new DataValueEvent(4, clock.next(), ValueType.DOUBLES, 0.001 * k + " 0.0005 0.01"));
                roq.accept(new DataValueEvent(5, clock.next(), ValueType.DOUBLES, "0.1 0.2 0.3 0.1 0.2 0.3 0.1 0.2 0.3 0.1 0.2 0.3"));
                Thread.sleep(10);
            }
            check(roq.flush(30_000), "the RoQ run recorded");
        }
        try (LoggerConnection c = new LoggerConnection(logger.viewerAddress(), new PlotData())) {
            return c.runs().stream().filter(r -> r.nodes().size() == 6).findFirst().orElseThrow().runId();
        }
    }

    /** Each plot as "title·unit", joined by "|". */
    private static String titlesAndUnits(ViewerWindow w) {
        StringBuilder b = new StringBuilder();
        for (PlotView v : w.plots().plots()) {
            b.append(b.length() == 0 ? "" : "|").append(v.title()).append('·').append(v.unit());
        }
        return b.toString();
    }

    private static <T> T onEdt(java.util.concurrent.Callable<T> c) throws Exception {
        return OnEdt.call(c);
    }

    private static void click(java.awt.Container root, String name) {
        for (java.awt.Component c : root.getComponents()) {
            if (c instanceof javax.swing.AbstractButton b && name.equals(b.getName())) {
                b.doClick();
                return;
            }
            if (c instanceof java.awt.Container child) {
                click(child, name);
            }
        }
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
