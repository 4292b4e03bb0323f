package org.fdnet.roq.view;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.GridLayout;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import javax.imageio.ImageIO;
import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import org.fdnet.roq.sim.Heightfield;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.viewer.legible.LegibleFont;

/**
 * The content of the demo window: the robot and its course drawn by a {@link RoqPainter} (with the path so far)
 * above a row of live figures. Fed on the event dispatch thread through {@link #show}; it keeps its own copy of the
 * snapshot. Paints without a screen too, so {@link #writePng} works headless.
 */
public final class RoqDemoPanel extends JPanel {
    private static final int MAX_PATH = 20_000;

    private final Heightfield terrain;
    private final SensorSnapshot snapshot = new SensorSnapshot();
    private final RoqPainter painter = new RoqPainter();
    private final View view = new View();
    private double[] path = new double[512];
    private int points;
    private long updates;
    private final JLabel time = figure();
    private final JLabel distance = figure();
    private final JLabel margin = figure();
    private final JLabel probing = figure();
    private final JLabel events = figure();
    private final JLabel loop = figure();
    private final JLabel title = new JLabel(" ");

    public RoqDemoPanel(Heightfield terrain) {
        super(new BorderLayout());
        this.terrain = terrain;
        view.setPreferredSize(new Dimension(1200, 640));
        add(view, BorderLayout.CENTER);
        JPanel figures = new JPanel(new GridLayout(2, 3, 16, 4));
        figures.setBorder(BorderFactory.createEmptyBorder(6, 10, 8, 10));
        for (JLabel l : new JLabel[] {time, distance, margin, probing, events, loop}) {
            figures.add(l);
        }
        add(figures, BorderLayout.SOUTH);
        title.setName("title");
        title.setBorder(BorderFactory.createEmptyBorder(4, 10, 2, 10));
        add(title, BorderLayout.NORTH);
        show(null, DemoFigures.none());
    }

    /**
     * Shows what runs (the network's and course's names) above the robot, in a font that has the names'
     * characters; when no installed font has them, that line says so once, naming the package to install.
     */
    public void title(String text) {
        LegibleFont.Choice c = LegibleFont.forNames(title.getFont(), List.of(text));
        title.setFont(c.font());
        title.setText(c.legible() ? text : text + " — " + c.warning());
    }

    /** The header line (tests: the names legible). */
    public JLabel titleLabel() {
        return title;
    }

    private static JLabel figure() {
        JLabel l = new JLabel();
        l.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 13));
        return l;
    }

    /** Shows a new snapshot (copied; null keeps the last) and figures. Call on the event dispatch thread. */
    public void show(SensorSnapshot s, DemoFigures f) {
        if (s != null) {
            snapshot.copyFrom(s);
            appendPath(s.groundTruthBodyPosition(0), s.groundTruthBodyPosition(1));
            updates++;
        }
        time.setText(String.format(Locale.ROOT, "sim time   %7.1f s", f.simTime()));
        distance.setText(String.format(Locale.ROOT, "distance   %7.3f m%s", f.distance(), f.fallen() ? "  FALLEN" : ""));
        margin.setText("stability margin " + DemoFigures.metres(f.margin()) + " (min "
                + DemoFigures.metres(f.smallestMargin()) + ")");
        probing.setText("probes " + DemoFigures.count(f.probes()) + "  fragile found " + DemoFigures.count(f.fragileFound())
                + " avoided " + DemoFigures.count(f.fragileAvoided()) + " broken " + f.brokenCells());
        events.setText(String.format(Locale.ROOT, "events logged %,d", f.events()));
        loop.setText(String.format(Locale.ROOT, "loop p99 %.1f µs  overruns %,d", f.loopP99Micros(), f.overruns()));
        time.setForeground(f.fallen() ? Color.RED.darker() : null);
        view.repaint();
    }

    /**
     * Adds a point of the body's path without a snapshot (a picture drawn after the run from its recorded trail).
     * Call on the event dispatch thread.
     */
    public void trace(double x, double y) {
        appendPath(x, y);
    }

    private void appendPath(double x, double y) {
        if (points > 0 && Math.hypot(path[2 * points - 2] - x, path[2 * points - 1] - y) < 0.005) {
            return;
        }
        if (points == MAX_PATH) {
            System.arraycopy(path, 2, path, 0, 2 * (points - 1));
            points--;
        }
        if (2 * points + 2 > path.length) {
            path = Arrays.copyOf(path, Math.min(2 * MAX_PATH, path.length * 2));
        }
        path[2 * points] = x;
        path[2 * points + 1] = y;
        points++;
    }

    /** Snapshots shown so far. */
    public long updates() {
        return updates;
    }

    /** Points of the path so far. */
    public int pathPoints() {
        return points;
    }

    /**
     * Renders the whole panel (view and figures) at its current size, or at its preferred size when it has none
     * (never laid out in a window), into a PNG. Call on the event dispatch thread.
     */
    public void writePng(Path file) throws IOException {
        if (getWidth() <= 0 || getHeight() <= 0) {
            setSize(getPreferredSize());
        }
        doLayout();
        for (java.awt.Component c : getComponents()) {
            if (c instanceof JComponent j) {
                j.doLayout();
            }
        }
        BufferedImage image = new BufferedImage(getWidth(), getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            printAll(g);
        } finally {
            g.dispose();
        }
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        if (!ImageIO.write(image, "png", file.toFile())) {
            throw new IOException("no PNG writer in this JVM for " + file);
        }
    }

    /** The painted robot and course. */
    private final class View extends JComponent {
        @Override
        protected void paintComponent(Graphics g) {
            painter.paint((Graphics2D) g, snapshot, terrain, new Rectangle(0, 0, getWidth(), getHeight()), path, points);
        }
    }
}
