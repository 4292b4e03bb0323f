package org.fdnet.viewer.ui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Stroke;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Function;
import javax.swing.JComponent;
import javax.swing.Timer;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.data.Series;

/**
 * One plot: a canvas drawing the series a {@link PlotData} holds that were chosen for it (all of them by
 * default), one lane per unit (each with its own value axis — a plot of a {@link PlotGrid} holds one unit), the
 * time axis, and a legend beside the lines ({@link #setLegendVisible hideable}) that reads every series' value
 * at the time cursor. The time window, pause and cursor live in a {@link TimeAxis} that all the plots of a window
 * share: live, the window ends at the newest sample; paused, it stays where it is. Mouse wheel zooms, dragging
 * pans (and pauses), space pauses and resumes, double click returns to live, and the mouse places the cursor.
 * Each series is reduced to a min/max per pixel column, so a frame costs the visible samples once, not a shape
 * per sample. On a time axis of its own it repaints itself at {@link #FRAMES_PER_SECOND} while shown; on a shared
 * one, its {@link PlotGrid} does, for all its plots at once.
 */
public final class PlotPanel extends JComponent {
    public static final int FRAMES_PER_SECOND = 30;
    private static final Color[] PALETTE = {
        new Color(0x1f77b4), new Color(0xd62728), new Color(0x2ca02c), new Color(0xff7f0e), new Color(0x9467bd),
        new Color(0x8c564b), new Color(0xe377c2), new Color(0x17becf), new Color(0xbcbd22), new Color(0x7f7f7f)};
    private static final DateTimeFormatter CLOCK = DateTimeFormatter.ofPattern("HH:mm:ss.SSS").withZone(ZoneId.systemDefault());
    private static final int LEFT = 64;
    private static final int RIGHT = 14;
    private static final int TOP = 8;
    private static final int BOTTOM = 26;
    private static final int LANE_GAP = 10;
    private static final int LEGEND_MAX = 210;
    private static final int SMOOTH_POINTS = 600;
    private static final Stroke SMOOTH = new BasicStroke(1.3f);

    private final TimeAxis axis;
    private final boolean ownAxis;
    private final Function<PlotData, List<Series>> choice;
    private final Timer repaint;
    private final AtomicLong frames = new AtomicLong();
    private volatile PlotData data;
    private volatile long newestPainted = Long.MIN_VALUE;
    private volatile boolean legendVisible = true;
    private int dragX;
    private long dragEnd;
    private final List<ColumnSummary> summaries = new ArrayList<>();
    private int[] xs = new int[0];
    private int[] ys = new int[0];

    /** A plot of every series of {@code data}, on a time axis of its own, repainting itself at its frame rate. */
    public PlotPanel(PlotData data) {
        this(data, new TimeAxis(data::lastTime), PlotData::series, true);
    }

    /**
     * A plot of the series {@code choice} picks from the data, on a shared time axis whose owner ticks it and
     * repaints the plots ({@link PlotGrid}).
     */
    public PlotPanel(PlotData data, TimeAxis axis, Function<PlotData, List<Series>> choice) {
        this(data, axis, choice, false);
    }

    private PlotPanel(PlotData data, TimeAxis axis, Function<PlotData, List<Series>> choice, boolean ownAxis) {
        this.data = data;
        this.axis = axis;
        this.ownAxis = ownAxis;
        this.choice = choice;
        setPreferredSize(new Dimension(900, 560));
        setMinimumSize(new Dimension(200, 90));
        setFocusable(true);
        setOpaque(true);
        repaint = new Timer(1000 / FRAMES_PER_SECOND, e -> repaint());
        repaint.setCoalesce(true);
        MouseAdapter mouse = new MouseAdapter() {
            @Override
            public void mouseMoved(MouseEvent e) {
                setCursorX(e.getX());
            }

            @Override
            public void mouseExited(MouseEvent e) {
                axis.setCursor(TimeAxis.NO_CURSOR);
            }

            @Override
            public void mousePressed(MouseEvent e) {
                requestFocusInWindow();
                dragX = e.getX();
                dragEnd = axis.viewEnd();
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                long shift = (long) ((double) (e.getX() - dragX) / plotWidth(getWidth()) * axis.windowMicros());
                axis.panTo(dragEnd - shift);
                setCursorX(e.getX());
            }

            @Override
            public void mouseClicked(MouseEvent e) {
                if (e.getClickCount() == 2) {
                    axis.setPaused(false);
                }
            }

            @Override
            public void mouseWheelMoved(MouseWheelEvent e) {
                axis.zoom(Math.pow(1.25, e.getPreciseWheelRotation()));
            }
        };
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
        addKeyListener(new KeyAdapter() {
            @Override
            public void keyPressed(KeyEvent e) {
                if (e.getKeyCode() == KeyEvent.VK_SPACE) {
                    axis.setPaused(!axis.paused());
                }
            }
        });
    }

    @Override
    public void addNotify() {
        super.addNotify();
        if (ownAxis) {
            repaint.start();
        }
    }

    @Override
    public void removeNotify() {
        repaint.stop();
        super.removeNotify();
    }

    public PlotData data() {
        return data;
    }

    /** Draws from other data from the next frame on (live, a replay, a history). */
    public void setData(PlotData next) {
        data = next;
    }

    /** The series this plot draws now. */
    public List<Series> shownSeries() {
        return choice.apply(data);
    }

    public TimeAxis axis() {
        return axis;
    }

    /** Paused, the view keeps its place while values keep arriving; resumed, it follows the newest again. */
    public void setPaused(boolean pause) {
        axis.setPaused(pause);
    }

    public boolean paused() {
        return axis.paused();
    }

    /** Multiplies the width of the time window ({@code < 1} zooms in). */
    public void zoom(double factor) {
        axis.zoom(factor);
    }

    public long windowMicros() {
        return axis.windowMicros();
    }

    public void setWindowMicros(long micros) {
        axis.setWindowMicros(micros);
    }

    /** Shows {@code from .. to} (µs) and pauses there (history). */
    public void showRange(long from, long to) {
        axis.showRange(from, to);
    }

    /** The time (µs) at the right edge of the plot. */
    public long viewEnd() {
        return axis.viewEnd();
    }

    public long viewStart() {
        return axis.viewStart();
    }

    /** Frames painted so far. */
    public long frames() {
        return frames.get();
    }

    /** The newest sample time (µs) the last frame drew, {@link Long#MIN_VALUE} before any. */
    public long newestPainted() {
        return newestPainted;
    }

    /** Places the time cursor at x (pixels) of this plot; outside the lines, -1 for instance, hides it. */
    public void setCursorX(int x) {
        int w = plotWidth(getWidth());
        axis.setCursor(x >= LEFT && x < LEFT + w
                ? axis.viewStart() + (long) ((double) (x - LEFT) / w * axis.windowMicros()) : TimeAxis.NO_CURSOR);
    }

    /** The legend beside the lines (with the values at the cursor), or none: the lines take the whole width. */
    public void setLegendVisible(boolean visible) {
        legendVisible = visible;
        repaint();
    }

    public boolean legendVisible() {
        return legendVisible;
    }

    private int legendWidth(int width) {
        return legendVisible ? Math.min(LEGEND_MAX, width / 4) : 0;
    }

    private int plotWidth(int width) {
        return Math.max(10, width - LEFT - RIGHT - legendWidth(width));
    }

    @Override
    protected void paintComponent(Graphics g) {
        paintPlot((Graphics2D) g, getWidth(), getHeight());
    }

    /** Draws one frame into any graphics (the screen, an image for {@code --screenshot}, the bench). */
    public void paintPlot(Graphics2D g, int width, int height) {
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, width, height);
        g.setFont(getFont() != null ? getFont().deriveFont(11f) : new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        if (ownAxis) {
            axis.tick();
        }
        long end = axis.viewEnd();
        long window = axis.windowMicros();
        long start = end - window;
        List<Series> shown = shownSeries();
        Map<String, List<Series>> lanes = new LinkedHashMap<>();
        for (Series s : shown) {
            lanes.computeIfAbsent(s.unit(), u -> new ArrayList<>()).add(s);
        }
        int plotWidth = plotWidth(width);
        int bottom = height - BOTTOM;
        if (lanes.isEmpty()) {
            g.setColor(Color.GRAY);
            g.drawString("no values yet: drag Datas here from the tree (values arrive as the network writes them)",
                    LEFT, height / 2);
            frames.incrementAndGet();
            return;
        }
        int laneHeight = Math.max(20, (bottom - TOP - LANE_GAP * (lanes.size() - 1)) / lanes.size());
        ensureColumns(plotWidth, shown.size() + 8);
        long newest = Long.MIN_VALUE;
        int lane = 0;
        int colour = 0;
        long cursor = axis.cursor();
        boolean cursorShown = cursor != TimeAxis.NO_CURSOR && cursor >= start && cursor <= end;
        List<LegendRow> legend = new ArrayList<>();
        for (Map.Entry<String, List<Series>> e : lanes.entrySet()) {
            int top = TOP + lane * (laneHeight + LANE_GAP);
            List<Series> laneSeries = e.getValue();
            double[] raw = {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};
            for (int i = 0; i < laneSeries.size() && colour + i < summaries.size(); i++) {
                ColumnSummary summary = summaries.get(colour + i);
                summary.summarise(laneSeries.get(i), start, end, plotWidth);
                summary.widen(raw);
            }
            double[] range = padded(raw);
            paintLaneFrame(g, e.getKey(), top, laneHeight, plotWidth, range);
            for (Series s : laneSeries) {
                if (colour >= summaries.size()) {
                    break; // a series appeared during this frame: drawn from the next one
                }
                ColumnSummary summary = summaries.get(colour);
                Color c = PALETTE[colour++ % PALETTE.length];
                paintSeries(g, summary, c, top, laneHeight, plotWidth, range);
                newest = Math.max(newest, summary.newest());
                Series.Sample near = cursorShown ? s.heldAt(cursor) : null;
                legend.add(new LegendRow(s, c, near == null ? "" : String.format("%.4g%s", near.value(),
                        s.unit().isEmpty() ? "" : " " + s.unit())));
            }
            lane++;
        }
        paintTimeAxis(g, start, end, plotWidth, bottom);
        if (cursorShown) {
            int x = LEFT + (int) ((double) (cursor - start) / window * plotWidth);
            g.setColor(new Color(0x55, 0x55, 0x55));
            g.drawLine(x, TOP, x, bottom);
        }
        if (legendVisible) {
            paintLegend(g, legend, cursorShown ? cursor : TimeAxis.NO_CURSOR, LEFT + plotWidth + RIGHT, legendWidth(width),
                    bottom);
        } else if (cursorShown) {
            List<String> lines = new ArrayList<>();
            legend.forEach(r -> lines.add(r.series().name() + " = " + (r.value().isEmpty() ? "—" : r.value())));
            paintReadout(g, LEFT + (int) ((double) (cursor - start) / window * plotWidth), cursor, lines, plotWidth, bottom);
        }
        newestPainted = newest;
        frames.incrementAndGet();
    }

    private record LegendRow(Series series, Color colour, String value) {
    }

    /** The legend beside the lines: a row per series, with its value at the cursor at the row's right end. */
    private void paintLegend(Graphics2D g, List<LegendRow> rows, long cursor, int x, int w, int bottom) {
        FontMetrics fm = g.getFontMetrics();
        int y = TOP + fm.getAscent();
        boolean values = cursor != TimeAxis.NO_CURSOR;
        if (values) {
            g.setColor(Color.DARK_GRAY);
            g.drawString("at " + CLOCK.format(Instant.ofEpochSecond(cursor / 1_000_000, (cursor % 1_000_000) * 1000)), x, y);
            y += fm.getHeight() + 2;
        }
        for (int i = 0; i < rows.size(); i++) {
            if (y + fm.getHeight() > bottom && i < rows.size() - 1) {
                g.setColor(Color.GRAY);
                g.drawString("… " + (rows.size() - i) + " more", x, y);
                return;
            }
            LegendRow r = rows.get(i);
            String value = values ? (r.value().isEmpty() ? "—" : r.value()) : "";
            int valueWidth = value.isEmpty() ? 0 : fm.stringWidth(value) + 8;
            g.setColor(r.colour());
            g.fillRect(x, y - 8, 8, 8);
            g.setColor(Color.DARK_GRAY);
            g.drawString(fit(fm, r.series().name(), w - 14 - valueWidth), x + 12, y);
            if (!value.isEmpty()) {
                g.setColor(Color.BLACK);
                g.drawString(value, x + w - fm.stringWidth(value) - 4, y);
            }
            y += fm.getHeight() + 1;
        }
    }

    /** The text, shortened from the front ("…" + its end) when wider than {@code w}: a node's name ends in what tells it apart. */
    private static String fit(FontMetrics fm, String text, int w) {
        if (fm.stringWidth(text) <= w) {
            return text;
        }
        for (int cut = 1; cut < text.length(); cut++) {
            String shorter = "…" + text.substring(cut);
            if (fm.stringWidth(shorter) <= w) {
                return shorter;
            }
        }
        return "…";
    }

    private void ensureColumns(int w, int seriesCount) {
        if (xs.length < 4 * w + 2) {
            xs = new int[4 * w + 2];
            ys = new int[4 * w + 2];
        }
        while (summaries.size() < seriesCount) {
            summaries.add(new ColumnSummary());
        }
    }

    private static double[] padded(double[] r) {
        if (r[0] > r[1]) {
            return new double[] {0, 1};
        }
        if (r[1] - r[0] < 1e-12) {
            double pad = Math.max(1e-9, Math.abs(r[0]) * 0.1 + 0.5);
            return new double[] {r[0] - pad, r[1] + pad};
        }
        double pad = (r[1] - r[0]) * 0.06;
        return new double[] {r[0] - pad, r[1] + pad};
    }

    private void paintLaneFrame(Graphics2D g, String unit, int top, int h, int w, double[] range) {
        g.setColor(new Color(0xf7, 0xf8, 0xfa));
        g.fillRect(LEFT, top, w, h);
        g.setColor(new Color(0xc8, 0xcc, 0xd2));
        g.drawRect(LEFT, top, w, h);
        FontMetrics fm = g.getFontMetrics();
        int ticks = Math.max(3, Math.min(6, h / 30));
        double step = niceStep((range[1] - range[0]) / ticks);
        for (double v = Math.ceil(range[0] / step) * step; v <= range[1]; v += step) {
            int y = top + h - (int) ((v - range[0]) / (range[1] - range[0]) * h);
            g.setColor(new Color(0xe3, 0xe6, 0xea));
            g.drawLine(LEFT + 1, y, LEFT + w - 1, y);
            g.setColor(Color.DARK_GRAY);
            String label = formatValue(v, step);
            g.drawString(label, LEFT - 6 - fm.stringWidth(label), y + fm.getAscent() / 2 - 1);
        }
        Graphics2D rotated = (Graphics2D) g.create();
        rotated.rotate(-Math.PI / 2);
        String title = unit.isEmpty() ? "(no unit)" : unit;
        rotated.setColor(new Color(0x44, 0x44, 0x55));
        rotated.drawString(title, -(top + h / 2 + fm.stringWidth(title) / 2), 12);
        rotated.dispose();
    }

    private void paintSeries(Graphics2D g, ColumnSummary summary, Color c, int top, int h, int w, double[] range) {
        int n = summary.polyline(xs, ys, LEFT, top, h, range);
        Graphics2D clip = (Graphics2D) g.create(LEFT, top, w + 1, h + 1);
        clip.translate(-LEFT, -top);
        clip.setColor(c);
        if (n < SMOOTH_POINTS) {
            // few points: a smooth, slightly wider line; dense series stay 1 px and aliased (a frame's budget)
            clip.setStroke(SMOOTH);
            clip.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        }
        clip.drawPolyline(xs, ys, n);
        clip.dispose();
    }

    private void paintTimeAxis(Graphics2D g, long start, long end, int w, int bottom) {
        FontMetrics fm = g.getFontMetrics();
        long step = (long) niceStep((end - start) / 6.0);
        step = Math.max(1, step);
        g.setColor(Color.DARK_GRAY);
        for (long t = (start / step + 1) * step; t <= end; t += step) {
            int x = LEFT + (int) ((double) (t - start) / (end - start) * (w - 1));
            g.drawLine(x, bottom, x, bottom + 4);
            String label = CLOCK.format(Instant.ofEpochSecond(t / 1_000_000, (t % 1_000_000) * 1000));
            g.drawString(label, x - fm.stringWidth(label) / 2, bottom + 5 + fm.getAscent());
        }
        boolean paused = axis.paused();
        String width = String.format("window %.3g s", (end - start) / 1e6) + (paused ? " · PAUSED" : "");
        int wx = LEFT + w - 6 - fm.stringWidth(width);
        g.setColor(new Color(255, 255, 255, 210));
        g.fillRect(wx - 3, TOP + 3, fm.stringWidth(width) + 6, fm.getHeight());
        g.setColor(paused ? new Color(0xb0, 0x30, 0x30) : Color.DARK_GRAY);
        g.drawString(width, wx, TOP + 3 + fm.getAscent());
    }

    private void paintReadout(Graphics2D g, int x, long time, List<String> lines, int w, int bottom) {
        FontMetrics fm = g.getFontMetrics();
        List<String> shown = new ArrayList<>();
        shown.add(CLOCK.format(Instant.ofEpochSecond(time / 1_000_000, (time % 1_000_000) * 1000)));
        int max = Math.max(1, (bottom - TOP) / fm.getHeight() - 2);
        for (int i = 0; i < lines.size() && i < max; i++) {
            shown.add(lines.get(i));
        }
        if (lines.size() > max) {
            shown.add("… " + (lines.size() - max) + " more");
        }
        int boxW = 0;
        for (String s : shown) {
            boxW = Math.max(boxW, fm.stringWidth(s));
        }
        boxW += 12;
        int boxH = shown.size() * fm.getHeight() + 8;
        int bx = x + 10 + boxW > LEFT + w ? x - 10 - boxW : x + 10;
        g.setColor(new Color(255, 255, 240, 235));
        g.fillRect(bx, TOP + 4, boxW, boxH);
        g.setColor(Color.GRAY);
        g.drawRect(bx, TOP + 4, boxW, boxH);
        g.setColor(Color.BLACK);
        int y = TOP + 4 + fm.getAscent() + 4;
        for (String s : shown) {
            g.drawString(s, bx + 6, y);
            y += fm.getHeight();
        }
    }

    private static double niceStep(double raw) {
        if (!(raw > 0)) {
            return 1;
        }
        double mag = Math.pow(10, Math.floor(Math.log10(raw)));
        double f = raw / mag;
        return (f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10) * mag;
    }

    private static String formatValue(double v, double step) {
        if (Math.abs(v) < step * 1e-6) {
            v = 0;
        }
        int decimals = Math.max(0, (int) -Math.floor(Math.log10(step)));
        return decimals > 6 ? String.format("%.3g", v) : String.format("%." + decimals + "f", v);
    }
}
