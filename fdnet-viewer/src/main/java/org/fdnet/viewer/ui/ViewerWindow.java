package org.fdnet.viewer.ui;

import com.formdev.flatlaf.FlatLightLaf;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicReference;
import javax.imageio.ImageIO;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTable;
import javax.swing.JTextField;
import javax.swing.JToggleButton;
import javax.swing.ListSelectionModel;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.viewer.data.NodeSelection;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.data.UnitBook;
import org.fdnet.viewer.layout.LayoutFile;
import org.fdnet.viewer.layout.ReadyLayouts;
import org.fdnet.viewer.layout.ViewerLayout;
import org.fdnet.viewer.legible.LegibleFont;
import org.fdnet.viewer.source.LoggerConnection;
import org.fdnet.viewer.source.Replay;
import org.fdnet.viewer.source.ReplayLoader;
import org.fdnet.viewer.source.RunInfo;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The Network State Viewer's window: on the left the logger's runs (network, hosts, start, length) and the chosen
 * run's Datas as a tree ({@link NodeTree}); in the middle the plots on one time axis ({@link PlotGrid}); the tool
 * bar on top ({@link ViewerActions}: pause, live, zoom, history, plots, legend, layouts, CSV export) and the replay
 * bar at the bottom. The plots show the live values, a replayed run or a history, one at a time. A replayed run
 * whose Datas a shipped layout names ({@link ReadyLayouts}: RoQ's) opens with that layout unless one was chosen.
 *
 * <p>The editor opens a plot for its selected nodes with {@link #open(String, List)}.
 */
public final class ViewerWindow extends JFrame {
    /** The window's size when it opens: every control is on screen at this size. */
    public static final Dimension DEFAULT_SIZE = new Dimension(1200, 820);
    private static final Logger LOG = LoggerFactory.getLogger(ViewerWindow.class);
    private static final String[] SPEEDS = {"1×", "2×", "10×"};
    private static final int MEASURED_SOURCES = 3;

    private final LoggerConnection connection;
    private final PlotData live;
    private final PlotData replayed = new PlotData();
    private final UnitBook units = new UnitBook();
    private final PlotGrid grid;
    private final NodeTree tree = new NodeTree(units);
    private final RunTableModel runModel = new RunTableModel();
    private final JTable runTable = new JTable(runModel) {
        @Override
        public String getToolTipText(java.awt.event.MouseEvent e) {
            int row = rowAtPoint(e.getPoint());
            return row < 0 ? super.getToolTipText(e) : runModel.run(row).toString(); // network, hosts, start, id in full
        }
    };
    private final JLabel status = new JLabel(" ");
    private final JComboBox<String> speed = new JComboBox<>(SPEEDS);
    private final JTextField replayFrom = new JTextField("0", 5);
    private final JTextField replayTo = new JTextField("60", 5);
    private final JTextField lastSeconds = new JTextField("60", 6);
    private final JToggleButton pause = new JToggleButton("Pause");
    private final JToggleButton legend = new JToggleButton("Legend", true);
    private final AtomicReference<Replay> replay = new AtomicReference<>();
    private final HistoryLoader historyLoader = new HistoryLoader();
    private final ViewerActions actions = new ViewerActions();
    private boolean layoutChosen;

    private ViewerWindow(LoggerConnection connection, PlotData live) {
        super("FDNet Network State Viewer — logger " + connection.address());
        this.connection = connection;
        this.live = live;
        live.useUnits(units);
        replayed.useUnits(units);
        grid = new PlotGrid(live, units, this::say, this::watchLive);
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        registerActions();
        add(actions.toolBar(), BorderLayout.NORTH);
        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, picker(), grid);
        split.setDividerLocation(370);
        add(split, BorderLayout.CENTER);
        JPanel south = new JPanel(new BorderLayout());
        south.add(replayBar(), BorderLayout.NORTH);
        status.setName("status");
        status.setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        south.add(status, BorderLayout.SOUTH);
        add(south, BorderLayout.SOUTH);
        setSize(DEFAULT_SIZE);
    }

    /**
     * Opens a viewer on the logger's viewer service at {@code loggerAddress} ({@code HOST:PORT}) plotting
     * {@code nodeNames} live ({@code Module/Node}, optionally with a unit: {@code Module/Node[m]}), one plot per
     * unit. Call from any thread; answers the window once shown.
     *
     * @throws IOException when the logger cannot be reached
     * @throws IllegalArgumentException naming a node the logger does not know
     */
    public static ViewerWindow open(String loggerAddress, List<String> nodeNames) throws IOException {
        return open(loggerAddress, nodeNames, null);
    }

    /** As {@link #open(String, List)}, with the plots of {@code layout} (null: one plot per unit of the nodes). */
    public static ViewerWindow open(String loggerAddress, List<String> nodeNames, ViewerLayout layout) throws IOException {
        PlotData live = new PlotData();
        LoggerConnection connection = new LoggerConnection(loggerAddress, live);
        try {
            List<NodeSelection> selections = new ArrayList<>();
            nodeNames.forEach(n -> selections.add(NodeSelection.parse(n)));
            connection.watch(selections);
            List<LoggedNode> nodes = connection.dataNodes();
            List<RunInfo> runList = connection.runs();
            AtomicReference<ViewerWindow> window = new AtomicReference<>();
            SwingUtilities.invokeAndWait(() -> {
                FlatLightLaf.setup();
                ViewerWindow w = new ViewerWindow(connection, live);
                w.fill(nodes, runList);
                if (layout != null) {
                    w.applyLayout(layout);
                } else {
                    w.plotPerUnit(selections);
                }
                w.setLocationByPlatform(true);
                w.setVisible(true);
                window.set(w);
            });
            return window.get();
        } catch (java.lang.reflect.InvocationTargetException e) {
            connection.close();
            throw new IOException("the viewer window could not open: " + e.getCause(), e.getCause());
        } catch (InterruptedException e) {
            connection.close();
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while opening the viewer", e);
        } catch (IOException | RuntimeException e) {
            connection.close();
            throw e;
        }
    }

    /** The plots. */
    public PlotGrid plots() {
        return grid;
    }

    /** The values streamed live from the logger. */
    public PlotData liveData() {
        return live;
    }

    /** The values of the run being replayed. */
    public PlotData replayData() {
        return replayed;
    }

    /**
     * The Datas Export… writes, of the run chosen on the left: those chosen in the tree (a component stands for its
     * Data), else those plotted.
     */
    List<LoggedNode> exportableNodes() {
        RunInfo run = selectedRun();
        if (run == null) {
            return List.of();
        }
        java.util.Set<String> names = new java.util.LinkedHashSet<>();
        tree.chosen().forEach(s -> names.add(dataName(s.name())));
        if (names.isEmpty()) {
            grid.shownSeries().forEach(s -> names.add(dataName(s.name())));
        }
        return run.nodes().stream().filter(n -> names.contains(LoggerConnection.label(n))).toList();
    }

    private static String dataName(String series) {
        int component = series.indexOf('[');
        return component < 0 ? series : series.substring(0, component);
    }

    /** The run chosen on the left, or null. */
    RunInfo exportRun() {
        return selectedRun();
    }

    void showStatus(String text) {
        status.setText(text);
    }

    public LoggerConnection connection() {
        return connection;
    }

    /** The current replay, or null. */
    public Replay replay() {
        return replay.get();
    }

    public String statusText() {
        return status.getText();
    }

    private void say(String text) {
        status.setText(text);
    }

    /**
     * The one place the tool bar's actions are registered, in their order; another action (an exporter) is one more
     * {@link ViewerActions#add} here.
     */
    private void registerActions() {
        pause.setName("pause");
        pause.addActionListener(e -> grid.axis().setPaused(pause.isSelected()));
        actions.add(pause, "keep the plots where they are while values keep arriving (space)");
        actions.add("live", "Live", "back to the live values, following the newest (double click a plot)", this::showLive);
        actions.add("zoomIn", "Zoom in", "half the time window (mouse wheel)", () -> grid.axis().zoom(0.5));
        actions.add("zoomOut", "Zoom out", "double the time window (mouse wheel)", () -> grid.axis().zoom(2));
        actions.gap();
        actions.add("history", "History", "load the live Datas' values of the range beside from the logger",
                () -> loadHistory(lastSeconds.getText()));
        lastSeconds.setName("historyRange");
        actions.add(lastSeconds, "seconds (60 = the last minute) or clock times 08:09:30-08:10:15");
        actions.gap();
        actions.add("newPlot", "New plot", "a new plot at the bottom with the Datas chosen in the tree",
                () -> addChosen(grid.addPlot("plot " + (grid.plots().size() + 1))));
        legend.setName("legend");
        legend.addActionListener(e -> grid.setLegendVisible(legend.isSelected()));
        actions.add(legend, "the legend beside each plot, with the values at the time cursor; off: the lines take the width");
        actions.add("openLayout", "Open layout…", "plots and their series from a layout file", this::openLayout);
        actions.add("saveLayout", "Save layout…", "the plots and their series to a file (fdnet viewer --layout FILE)",
                this::saveLayout);
        actions.gap();
        actions.add("exportCsv", "CSV…", "the plotted values of the visible time window as CSV, as drawn", this::exportCsv);
        actions.add("export", ExportAction.NAME, ExportAction.TOOLTIP, new ExportAction(this));
    }

    private JPanel picker() {
        JPanel p = new JPanel(new BorderLayout(0, 4));
        p.setBorder(BorderFactory.createEmptyBorder(4, 4, 4, 4));
        runTable.setName("runs");
        runTable.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        runTable.getColumnModel().getColumn(0).setPreferredWidth(160);
        runTable.getColumnModel().getColumn(1).setPreferredWidth(44);
        runTable.getColumnModel().getColumn(2).setPreferredWidth(72);
        runTable.getColumnModel().getColumn(3).setPreferredWidth(68);
        runTable.setToolTipText("choose a run: its Datas show in the tree below, and Play replays it");
        runTable.getSelectionModel().addListSelectionListener(e -> {
            if (!e.getValueIsAdjusting() && runTable.getSelectedRow() >= 0) {
                tree.show(runModel.run(runTable.getSelectedRow()), live);
            }
        });
        JScrollPane runs = new JScrollPane(runTable);
        runs.setBorder(BorderFactory.createTitledBorder("Recorded runs"));
        runs.setPreferredSize(new Dimension(360, 150));
        p.add(runs, BorderLayout.NORTH);
        JScrollPane nodes = new JScrollPane(tree);
        nodes.setBorder(BorderFactory.createTitledBorder("Datas of the run (drag into a plot)"));
        p.add(nodes, BorderLayout.CENTER);
        JButton add = new JButton("Add to plot");
        add.setName("addToPlot");
        add.setToolTipText("add the chosen Datas to the last plot");
        add.addActionListener(e -> addChosen(grid.plots().isEmpty() ? grid.addPlot("plot 1")
                : grid.plots().get(grid.plots().size() - 1)));
        JButton fresh = new JButton("New plot");
        fresh.setName("addToNewPlot");
        fresh.setToolTipText("a new plot with the chosen Datas");
        fresh.addActionListener(e -> addChosen(grid.addPlot("plot " + (grid.plots().size() + 1))));
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        buttons.add(add);
        buttons.add(fresh);
        p.add(buttons, BorderLayout.SOUTH);
        return p;
    }

    private JPanel replayBar() {
        JPanel bar = new JPanel(new FlowLayout(FlowLayout.LEFT, 6, 4));
        bar.setBorder(BorderFactory.createTitledBorder("Replay the run chosen on the left"));
        JButton play = new JButton("Play");
        play.setName("play");
        play.addActionListener(e -> startReplay());
        JToggleButton hold = new JToggleButton("Pause replay");
        hold.setName("pauseReplay");
        hold.addActionListener(e -> {
            Replay r = replay.get();
            if (r != null) {
                if (hold.isSelected()) {
                    r.pause();
                } else {
                    r.resume();
                }
            }
        });
        speed.setName("speed");
        speed.addActionListener(e -> {
            Replay r = replay.get();
            if (r != null) {
                r.setSpeed(chosenSpeed());
            }
        });
        replayFrom.setName("replayFrom");
        replayTo.setName("replayTo");
        bar.add(new JLabel("from"));
        bar.add(replayFrom);
        bar.add(new JLabel("s to"));
        bar.add(replayTo);
        bar.add(new JLabel("s after the run's first value, at"));
        bar.add(speed);
        bar.add(play);
        bar.add(hold);
        return bar;
    }

    private void fill(List<LoggedNode> nodes, List<RunInfo> runList) {
        runModel.setRuns(runList);
        if (!runList.isEmpty()) {
            runTable.setRowSelectionInterval(0, 0);
        }
        status.setText(String.format("%d run%s recorded%s; plotting %d node(s) live — drag Datas from the tree into a"
                + " plot", runList.size(), runList.size() == 1 ? "" : "s", runList.isEmpty() ? "" : ", newest: "
                + runList.get(0), live.trackedSources().length));
        legibleNames(nodes);
        measureLengths(runList);
    }

    /** Each run's length, measured on a few of its Datas off the event thread, filled in as answers arrive. */
    private void measureLengths(List<RunInfo> runList) {
        for (RunInfo r : runList) {
            int[] ids = r.sourceIds();
            int[] some = java.util.Arrays.copyOf(ids, Math.min(ids.length, MEASURED_SOURCES));
            historyLoader.ask(() -> connection.span(some), span -> runModel.setLength(r.runId(),
                    span == null ? 0 : span[1] - span[0]), e -> LOG.debug("length of {}: {}", r, e.getMessage()));
        }
    }

    /**
     * The tree and the plots draw the nodes' names in a font that has their characters (Japanese names too);
     * when no installed font has them, the status bar says so, naming the package to install.
     */
    private void legibleNames(List<LoggedNode> nodes) {
        List<String> names = new ArrayList<>();
        nodes.forEach(n -> names.add(LoggerConnection.label(n)));
        LegibleFont.Choice c = LegibleFont.forNames(tree.getFont(), names);
        tree.setFont(c.font());
        grid.setFont(c.font());
        if (!c.legible()) {
            status.setText(c.warning());
        }
    }

    /** The font the node tree shows names in (tests: every name displayable). */
    public java.awt.Font namesFont() {
        return tree.getFont();
    }

    /** One plot per unit of the live selections, in their order. */
    private void plotPerUnit(List<NodeSelection> selections) {
        Map<String, List<NodeSelection>> byUnit = new LinkedHashMap<>();
        selections.forEach(s -> byUnit.computeIfAbsent(s.unit(), u -> new ArrayList<>()).add(s));
        byUnit.forEach((unit, list) -> grid.addSeries(grid.addPlot(String.join(", ",
                list.stream().map(NodeSelection::name).toList())), list));
        if (byUnit.isEmpty()) {
            grid.addPlot("plot 1");
        }
    }

    /** Shows a layout's plots (the live Datas it names are monitored); the one a replay keeps. */
    public void applyLayout(ViewerLayout layout) {
        layoutChosen = true;
        grid.apply(layout);
        legend.setSelected(layout.legendVisible());
        showRun(selectedRun());
    }

    private RunInfo selectedRun() {
        int row = runTable.getSelectedRow();
        return row < 0 ? null : runModel.run(row);
    }

    private void showRun(RunInfo run) {
        if (run != null) {
            tree.show(run, grid.data());
        }
    }

    /** Monitors live the nodes a plot now holds (in live mode); a node the logger lacks is said, not thrown. */
    private void watchLive(List<NodeSelection> entries) {
        if (grid.data() != live) {
            return;
        }
        List<LoggedNode> nodes = new ArrayList<>();
        for (NodeSelection s : entries) {
            try {
                nodes.add(connection.resolve(new NodeSelection(s.node(), "")));
            } catch (IllegalArgumentException | IOException e) {
                status.setText(e.getMessage());
            }
        }
        try {
            connection.watchNodes(nodes);
        } catch (IOException e) {
            LOG.warn("monitor request failed: {}", e.getMessage());
            status.setText("the logger refused the monitor request: " + e.getMessage());
        }
    }

    private void addChosen(PlotView plot) {
        List<NodeSelection> chosen = tree.chosen();
        if (chosen.isEmpty()) {
            status.setText("choose one or more Datas in the tree first (or drag them into a plot)");
            return;
        }
        int n = grid.addSeries(plot, chosen);
        if (n > 0) {
            status.setText("added " + n + " Data(s) to '" + plot.title() + "'");
        }
    }

    /** The node tree (tests drag from it). */
    NodeTree tree() {
        return tree;
    }

    private void showLive() {
        pause.setSelected(false);
        grid.show(live);
        grid.axis().setPaused(false);
        showRun(selectedRun());
    }

    private double chosenSpeed() {
        String s = (String) speed.getSelectedItem();
        return Double.parseDouble(s.substring(0, s.length() - 1));
    }

    private void loadHistory(String rangeText) {
        long newest = live.lastTime() == Long.MIN_VALUE ? System.currentTimeMillis() * 1000 : live.lastTime();
        long[] range;
        try {
            range = HistoryRange.parse(rangeText, newest, java.time.ZoneId.systemDefault());
        } catch (IllegalArgumentException e) {
            status.setText(e.getMessage());
            return;
        }
        PlotData history = new PlotData();
        history.useUnits(units);
        copyTracking(live, history);
        status.setText("loading history " + rangeText.trim() + " from the logger ...");
        historyLoader.load(connection, live.trackedSources(), range[0], range[1], history, n -> {
            grid.show(history);
            grid.axis().showRange(range[0], range[1]);
            status.setText(String.format("history %s: %,d values from the logger (cache + database); press Live to return",
                    rangeText.trim(), n));
        }, e -> status.setText("history failed: " + e.getMessage()));
    }

    private static void copyTracking(PlotData from, PlotData to) {
        for (int id : from.trackedSources()) {
            var series = from.seriesOf(id);
            String name = series.isEmpty() ? "source " + id : series.get(0).name().replaceAll("\\[\\d+]$", "");
            to.track(id, name, series.isEmpty() ? "" : series.get(0).unit());
        }
    }

    private void openLayout() {
        JFileChooser chooser = new JFileChooser();
        if (chooser.showOpenDialog(this) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path file = chooser.getSelectedFile().toPath();
        try {
            applyLayout(LayoutFile.read(file));
            status.setText("layout " + file + ": " + grid.plots().size() + " plots");
        } catch (IOException | IllegalArgumentException e) {
            status.setText("layout not opened: " + e.getMessage());
        }
    }

    private void saveLayout() {
        JFileChooser chooser = new JFileChooser();
        chooser.setSelectedFile(new java.io.File("fdnet-viewer.layout"));
        if (chooser.showSaveDialog(this) == JFileChooser.APPROVE_OPTION) {
            saveLayout(chooser.getSelectedFile().toPath());
        }
    }

    /** Writes the plots to a layout file ({@code fdnet viewer --layout FILE} opens it again). */
    public void saveLayout(Path file) {
        try {
            LayoutFile.write(grid.currentLayout(), file);
            status.setText("layout saved to " + file);
        } catch (IOException e) {
            status.setText("layout not saved to " + file + ": " + e.getMessage());
        }
    }

    private void exportCsv() {
        JFileChooser chooser = new JFileChooser();
        chooser.setSelectedFile(new java.io.File("fdnet-viewer.csv"));
        if (chooser.showSaveDialog(this) == JFileChooser.APPROVE_OPTION) {
            exportCsv(chooser.getSelectedFile().toPath());
        }
    }

    /** Writes every plotted series' values in the visible time window as CSV; answers the rows written, -1 when it failed. */
    public long exportCsv(Path file) {
        try {
            long rows = CsvExport.write(file, grid.shownSeries(), grid.axis().viewStart(), grid.axis().viewEnd());
            status.setText(String.format("exported %,d values of the visible window to %s", rows, file));
            return rows;
        } catch (IOException e) {
            status.setText("CSV export to " + file + " failed: " + e.getMessage());
            return -1;
        }
    }

    /**
     * Starts replaying the chosen run's range at the chosen speed into the plots (also used by tests). Without a
     * layout chosen, a run a shipped layout fits opens with it.
     */
    public void startReplay() {
        RunInfo run = selectedRun();
        if (run == null) {
            status.setText("the logger has recorded no run yet");
            return;
        }
        double fromS;
        double toS;
        try {
            fromS = Double.parseDouble(replayFrom.getText().trim());
            toS = Double.parseDouble(replayTo.getText().trim());
        } catch (NumberFormatException e) {
            status.setText("replay range: 'from' and 'to' must be seconds, e.g. 0 and 60");
            return;
        }
        try {
            Replay r = ReplayLoader.load(connection, run, fromS, toS, chosenSpeed(), replayed);
            Replay old = replay.getAndSet(r);
            if (old != null) {
                old.stop();
            }
            pause.setSelected(false);
            grid.show(replayed); // before a ready layout is applied: its Datas are replayed, not monitored live
            grid.axis().setPaused(false);
            String ready = "";
            if (!layoutChosen) {
                Optional<ViewerLayout> fits = ReadyLayouts.forNodes(run.nodes().stream().map(LoggerConnection::label).toList());
                if (fits.isPresent()) {
                    grid.apply(fits.get());
                    legend.setSelected(fits.get().legendVisible());
                    layoutChosen = true;
                    ready = " in its ready layout";
                }
            }
            r.start();
            String range = fromS < 0 ? String.format("its last %.1f s", -fromS) : String.format("%.1f s .. %.1f s", fromS, toS);
            status.setText(String.format("replaying %s (run %d), %s: %,d values at %s%s", run.network().isEmpty()
                    ? "run " + run.runId() : run.network(), run.runId(), range, r.total(), speed.getSelectedItem(), ready));
            showRunWhenComponentsKnown(run);
        } catch (IOException | IllegalArgumentException e) {
            status.setText("replay failed: " + e.getMessage());
        }
    }

    /** The tree shows the components of vectors once the replay's first values made them known. */
    private void showRunWhenComponentsKnown(RunInfo run) {
        javax.swing.Timer once = new javax.swing.Timer(1500, e -> showRun(run));
        once.setRepeats(false);
        once.start();
    }

    /** Selects the run, range and speed of the replay bar (for scripted use and tests). */
    public void chooseReplay(int runId, double fromSeconds, double toSeconds, String speedLabel) {
        int row = runModel.rowOf(runId);
        if (row >= 0) {
            runTable.setRowSelectionInterval(row, row);
        }
        replayFrom.setText(Double.toString(fromSeconds));
        replayTo.setText(Double.toString(toSeconds));
        speed.setSelectedItem(speedLabel);
    }

    /** Paints the window into a PNG (for {@code --screenshot}). */
    public void screenshot(Path file) throws IOException {
        AtomicReference<BufferedImage> image = new AtomicReference<>();
        try {
            SwingUtilities.invokeAndWait(() -> {
                BufferedImage img = new BufferedImage(getWidth(), getHeight(), BufferedImage.TYPE_INT_RGB);
                Graphics2D g = img.createGraphics();
                getRootPane().paint(g);
                g.dispose();
                image.set(img);
            });
        } catch (java.lang.reflect.InvocationTargetException e) {
            throw new IOException("painting the window failed: " + e.getCause(), e.getCause());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
        ImageIO.write(image.get(), "png", file.toFile());
    }

    @Override
    public void dispose() {
        Replay r = replay.getAndSet(null);
        if (r != null) {
            r.stop();
        }
        historyLoader.close();
        connection.close();
        super.dispose();
    }
}
