package org.fdnet.viewer.ui;

import com.formdev.flatlaf.FlatLightLaf;
import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import javax.imageio.ImageIO;
import javax.swing.BorderFactory;
import javax.swing.DefaultListModel;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTextField;
import javax.swing.JToggleButton;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.viewer.data.NodeSelection;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.legible.LegibleFont;
import org.fdnet.viewer.source.LoggerConnection;
import org.fdnet.viewer.source.Replay;
import org.fdnet.viewer.source.ReplayLoader;
import org.fdnet.viewer.source.RunInfo;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The Network State Viewer's window: a node picker (the logger's Data nodes of its newest run) on the
 * left, the {@link PlotPanel} in the middle, a tool bar (pause, window width, history of the last N
 * seconds, CSV export) on top and the replay bar (run, range, speed, play/pause) at the bottom.
 *
 * <p>The editor opens a plot for its selected nodes with {@link #open(String, List)}.
 */
public final class ViewerWindow extends JFrame {
    private static final Logger LOG = LoggerFactory.getLogger(ViewerWindow.class);
    private static final String[] SPEEDS = {"1×", "2×", "10×"};

    private final LoggerConnection connection;
    private final PlotData live;
    private final PlotData replayed = new PlotData();
    private final PlotPanel livePlot;
    private final PlotPanel replayPlot;
    private final JPanel centre = new JPanel(new BorderLayout());
    private final DefaultListModel<LoggedNode> nodeModel = new DefaultListModel<>();
    private final JList<LoggedNode> nodeList = new JList<>(nodeModel);
    private final JLabel status = new JLabel(" ");
    private final JComboBox<RunInfo> runs = new JComboBox<>();
    private final java.util.Map<Integer, String> hostOfSource = new java.util.HashMap<>();
    private final JComboBox<String> speed = new JComboBox<>(SPEEDS);
    private final JTextField replayFrom = new JTextField("0", 5);
    private final JTextField replayTo = new JTextField("60", 5);
    private final JToggleButton pause = new JToggleButton("Pause");
    private final AtomicReference<Replay> replay = new AtomicReference<>();
    private final HistoryLoader historyLoader = new HistoryLoader();

    private ViewerWindow(LoggerConnection connection, PlotData live) {
        super("FDNet Network State Viewer — logger " + connection.address());
        this.connection = connection;
        this.live = live;
        livePlot = new PlotPanel(live);
        replayPlot = new PlotPanel(replayed);
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        add(toolBar(), BorderLayout.NORTH);
        centre.add(livePlot, BorderLayout.CENTER);
        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, picker(), centre);
        split.setDividerLocation(250);
        add(split, BorderLayout.CENTER);
        JPanel south = new JPanel(new BorderLayout());
        south.add(replayBar(), BorderLayout.NORTH);
        status.setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        south.add(status, BorderLayout.SOUTH);
        add(south, BorderLayout.SOUTH);
        setSize(1200, 720);
    }

    /**
     * Opens a viewer on the logger's viewer service at {@code loggerAddress} ({@code HOST:PORT}) plotting
     * {@code nodeNames} live ({@code Module/Node}, optionally with a unit: {@code Module/Node[m]}). Call from
     * any thread; answers the window once shown.
     *
     * @throws IOException when the logger cannot be reached
     * @throws IllegalArgumentException naming a node the logger does not know
     */
    public static ViewerWindow open(String loggerAddress, List<String> nodeNames) throws IOException {
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

    public PlotPanel livePlot() {
        return livePlot;
    }

    public PlotPanel replayPlot() {
        return replayPlot;
    }

    /** The nodes Export… writes: those selected in the list, else those plotted live. */
    List<LoggedNode> exportableNodes() {
        List<LoggedNode> chosen = nodeList.getSelectedValuesList();
        if (!chosen.isEmpty()) {
            return chosen;
        }
        List<LoggedNode> plotted = new ArrayList<>();
        for (int i = 0; i < nodeModel.size(); i++) {
            if (live.tracks(nodeModel.get(i).sourceId())) {
                plotted.add(nodeModel.get(i));
            }
        }
        return plotted;
    }

    /** The plot on show (live or replay). */
    PlotPanel shownPlot() {
        return (PlotPanel) centre.getComponent(0);
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

    private void fill(List<LoggedNode> nodes, List<RunInfo> runList) {
        if (!runList.isEmpty()) {
            RunInfo newest = runList.get(0);
            newest.nodesByHost().forEach(n -> {
                nodeModel.addElement(n);
                hostOfSource.put(n.sourceId(), newest.hostOf(n));
            });
        }
        runList.forEach(runs::addItem);
        status.setText(String.format("%d Datas in the newest run%s, %d runs recorded; plotting %d node(s)",
                nodeModel.size(), runList.isEmpty() ? "" : " (" + runList.get(0) + ")", runList.size(),
                live.trackedSources().length));
        legibleNames(nodes);
    }

    /**
     * The list and the plots draw the nodes' names in a font that has their characters (Japanese names too);
     * when no installed font has them, the status bar says so, naming the package to install.
     */
    private void legibleNames(List<LoggedNode> nodes) {
        List<String> names = new ArrayList<>();
        nodes.forEach(n -> names.add(LoggerConnection.label(n)));
        LegibleFont.Choice c = LegibleFont.forNames(nodeList.getFont(), names);
        nodeList.setFont(c.font());
        livePlot.setFont(c.font());
        replayPlot.setFont(c.font());
        if (!c.legible()) {
            status.setText(c.warning());
        }
    }

    /** The font the node list shows names in (tests: every name displayable). */
    public java.awt.Font namesFont() {
        return nodeList.getFont();
    }

    private JPanel toolBar() {
        JPanel bar = new JPanel(new FlowLayout(FlowLayout.LEFT, 6, 4));
        pause.addActionListener(e -> livePlot.setPaused(pause.isSelected()));
        JButton zoomIn = new JButton("Zoom in");
        zoomIn.addActionListener(e -> livePlot.zoom(0.5));
        JButton zoomOut = new JButton("Zoom out");
        zoomOut.addActionListener(e -> livePlot.zoom(2));
        JButton follow = new JButton("Live");
        follow.addActionListener(e -> {
            pause.setSelected(false);
            livePlot.setPaused(false);
            showPlot(livePlot);
        });
        JTextField lastSeconds = new JTextField("60", 12);
        lastSeconds.setToolTipText("seconds (60 = the last minute) or clock times 08:09:30-08:10:15");
        JButton history = new JButton("History");
        history.addActionListener(e -> loadHistory(lastSeconds.getText()));
        JButton export = new JButton("Export CSV…");
        export.addActionListener(e -> exportCsv());
        bar.add(pause);
        bar.add(follow);
        bar.add(zoomIn);
        bar.add(zoomOut);
        bar.add(new JLabel("  "));
        bar.add(history);
        bar.add(lastSeconds);
        bar.add(new JLabel("  "));
        bar.add(export);
        bar.add(new JButton(new ExportAction(this)));
        bar.add(new JLabel("   wheel: zoom · drag: pan · space: pause · double click: live"));
        return bar;
    }

    private JPanel picker() {
        JPanel p = new JPanel(new BorderLayout(0, 4));
        p.setBorder(BorderFactory.createEmptyBorder(4, 4, 4, 4));
        p.add(new JLabel("Logger's Data nodes (newest run, by host)"), BorderLayout.NORTH);
        nodeList.setCellRenderer((list, value, index, selected, focus) -> {
            String host = hostOfSource.getOrDefault(value.sourceId(), "");
            JLabel l = new JLabel((host.isEmpty() ? "" : host + ":  ") + LoggerConnection.label(value)
                    + (live.tracks(value.sourceId()) ? "  ●" : ""));
            l.setFont(list.getFont());
            l.setOpaque(true);
            l.setBorder(BorderFactory.createEmptyBorder(1, 4, 1, 4));
            l.setBackground(selected ? list.getSelectionBackground() : list.getBackground());
            l.setForeground(selected ? list.getSelectionForeground() : list.getForeground());
            return l;
        });
        p.add(new JScrollPane(nodeList), BorderLayout.CENTER);
        JButton plot = new JButton("Plot selected");
        plot.addActionListener(e -> plotSelected());
        p.add(plot, BorderLayout.SOUTH);
        return p;
    }

    private JPanel replayBar() {
        JPanel bar = new JPanel(new FlowLayout(FlowLayout.LEFT, 6, 4));
        bar.setBorder(BorderFactory.createTitledBorder("Replay a recorded run"));
        JButton play = new JButton("Play");
        play.addActionListener(e -> startReplay());
        JToggleButton hold = new JToggleButton("Pause replay");
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
        speed.addActionListener(e -> {
            Replay r = replay.get();
            if (r != null) {
                r.setSpeed(chosenSpeed());
            }
        });
        bar.add(runs);
        bar.add(new JLabel("from s"));
        bar.add(replayFrom);
        bar.add(new JLabel("to s (after the run's first value)"));
        bar.add(replayTo);
        bar.add(speed);
        bar.add(play);
        bar.add(hold);
        return bar;
    }

    private double chosenSpeed() {
        String s = (String) speed.getSelectedItem();
        return Double.parseDouble(s.substring(0, s.length() - 1));
    }

    private void showPlot(PlotPanel plot) {
        centre.removeAll();
        centre.add(plot, BorderLayout.CENTER);
        centre.revalidate();
        centre.repaint();
    }

    private void plotSelected() {
        List<LoggedNode> chosen = nodeList.getSelectedValuesList();
        if (chosen.isEmpty()) {
            status.setText("select one or more nodes in the list first");
            return;
        }
        try {
            connection.watchNodes(chosen);
            status.setText("plotting " + chosen.size() + " more node(s) live");
            nodeList.repaint();
        } catch (IOException e) {
            LOG.warn("monitor request failed: {}", e.getMessage());
            status.setText("the logger refused the monitor request: " + e.getMessage());
        }
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
        copyTracking(live, history);
        status.setText("loading history " + rangeText.trim() + " from the logger ...");
        historyLoader.load(connection, live.trackedSources(), range[0], range[1], history, n -> {
            PlotPanel plot = new PlotPanel(history);
            plot.showRange(range[0], range[1]);
            showPlot(plot);
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

    private void exportCsv() {
        JFileChooser chooser = new JFileChooser();
        chooser.setSelectedFile(new java.io.File("fdnet-viewer.csv"));
        if (chooser.showSaveDialog(this) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        PlotPanel shown = (PlotPanel) centre.getComponent(0);
        try {
            long rows = CsvExport.write(chooser.getSelectedFile().toPath(), shown.data().series(), shown.viewStart(),
                    shown.viewEnd());
            status.setText(String.format("exported %,d values of the visible window to %s", rows, chooser.getSelectedFile()));
        } catch (IOException e) {
            status.setText("CSV export to " + chooser.getSelectedFile() + " failed: " + e.getMessage());
        }
    }

    /** Starts replaying the chosen run's range at the chosen speed into the replay plot (also used by tests). */
    public void startReplay() {
        RunInfo run = (RunInfo) runs.getSelectedItem();
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
            showPlot(replayPlot);
            r.start();
            String range = fromS < 0 ? String.format("its last %.1f s", -fromS) : String.format("%.1f s .. %.1f s", fromS, toS);
            status.setText(String.format("replaying %s, %s: %,d values at %s", run, range, r.total(), speed.getSelectedItem()));
        } catch (IOException | IllegalArgumentException e) {
            status.setText("replay failed: " + e.getMessage());
        }
    }

    /** Selects the run, range and speed of the replay bar (for scripted use and tests). */
    public void chooseReplay(int runId, double fromSeconds, double toSeconds, String speedLabel) {
        for (int i = 0; i < runs.getItemCount(); i++) {
            if (runs.getItemAt(i).runId() == runId) {
                runs.setSelectedIndex(i);
            }
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
