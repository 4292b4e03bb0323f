package org.fdnet.viewer.ui;

import java.awt.GridLayout;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Consumer;
import javax.swing.JPanel;
import javax.swing.Timer;
import org.fdnet.viewer.data.NodeSelection;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.data.Series;
import org.fdnet.viewer.data.UnitBook;
import org.fdnet.viewer.layout.PlotSpec;
import org.fdnet.viewer.layout.ViewerLayout;

/**
 * The viewer's plots, top to bottom, on one {@link TimeAxis}: zoom, pan, pause and the time cursor of one are
 * those of all. Plots are added, split and removed; series are added to a plot only when their unit is the
 * plot's (a series in another unit is refused with the reason, to be put on a plot of its own). The grid shows
 * one {@link PlotData} at a time (live, a replay, a history) and turns into a {@link ViewerLayout} and back.
 */
public final class PlotGrid extends JPanel {
    private final TimeAxis axis;
    private final UnitBook units;
    private final Consumer<String> say;
    private final Consumer<List<NodeSelection>> added;
    private final List<PlotView> plots = new ArrayList<>();
    private final Timer frames;
    private PlotData data;
    private boolean legendVisible = true;

    /**
     * {@code say} shows a message (a refusal) to the user; {@code added} hears of the series added to a plot (the
     * window monitors them live).
     */
    PlotGrid(PlotData data, UnitBook units, Consumer<String> say, Consumer<List<NodeSelection>> added) {
        super(new GridLayout(0, 1));
        this.data = data;
        this.units = units;
        this.say = say;
        this.added = added;
        this.axis = new TimeAxis(data::lastTime);
        setName("plots");
        // one tick then one repaint of every plot: all plots of a frame end at the same instant
        frames = new Timer(1000 / PlotPanel.FRAMES_PER_SECOND, e -> {
            axis.tick();
            repaint();
        });
        frames.setCoalesce(true);
    }

    @Override
    public void addNotify() {
        super.addNotify();
        frames.start();
    }

    @Override
    public void removeNotify() {
        frames.stop();
        super.removeNotify();
    }

    public TimeAxis axis() {
        return axis;
    }

    public List<PlotView> plots() {
        return List.copyOf(plots);
    }

    public PlotData data() {
        return data;
    }

    /** Shows other data in every plot (live, a replay, a history); the axis follows its newest value. */
    void show(PlotData next) {
        data = next;
        axis.follow(next::lastTime);
        plots.forEach(p -> p.plot().setData(next));
    }

    /** A new empty plot at the bottom. */
    public PlotView addPlot(String title) {
        return insert(plots.size(), title);
    }

    /** A new empty plot right below {@code above}. */
    public PlotView addAfter(PlotView above, String title) {
        return insert(plots.indexOf(above) + 1, title);
    }

    private PlotView insert(int index, String title) {
        PlotView v = new PlotView(title, this, data, axis);
        v.plot().setLegendVisible(legendVisible);
        v.plot().setFont(getFont());
        plots.add(index, v);
        add(v, index);
        revalidate();
        repaint();
        return v;
    }

    public void removePlot(PlotView v) {
        if (plots.remove(v)) {
            super.remove(v);
            revalidate();
            repaint();
        }
    }

    /**
     * Adds series to a plot: each takes its unit from the selection or, without one, from what the viewer was told
     * ({@link UnitBook}); one whose unit is not the plot's is refused with the reason shown. Answers how many were added.
     */
    public int addSeries(PlotView plot, List<NodeSelection> selections) {
        int n = 0;
        for (NodeSelection s : selections) {
            String unit = s.unit().isEmpty() ? units.unitOf(s.name(), "") : s.unit();
            NodeSelection withUnit = new NodeSelection(s.name(), unit);
            if (plot.holds(withUnit)) {
                continue;
            }
            if (!plot.entries().isEmpty() && !plot.unit().equals(unit)) {
                say.accept(String.format("'%s' is in %s, the plot '%s' in %s: put it on a plot of its own (New plot or"
                        + " Split)", s.name(), unitName(unit), plot.title(), unitName(plot.unit())));
                continue;
            }
            units.learn(withUnit);
            plot.addEntry(withUnit);
            n++;
        }
        if (n > 0) {
            added.accept(plot.entries());
        }
        return n;
    }

    private static String unitName(String unit) {
        return unit.isEmpty() ? "no unit" : unit;
    }

    /** The legends beside every plot, or hidden. */
    public void setLegendVisible(boolean visible) {
        legendVisible = visible;
        plots.forEach(p -> p.plot().setLegendVisible(visible));
    }

    public boolean legendVisible() {
        return legendVisible;
    }

    /** Replaces the plots with the layout's, learning its units, and takes its time window and legend. */
    public void apply(ViewerLayout layout) {
        new ArrayList<>(plots).forEach(this::removePlot);
        for (PlotSpec spec : layout.plots()) {
            spec.series().forEach(units::learn);
            PlotView v = addPlot(spec.title());
            addSeries(v, spec.series());
        }
        axis.setWindowMicros((long) (layout.windowSeconds() * 1e6));
        setLegendVisible(layout.legendVisible());
    }

    /** What the grid shows now, as a layout. */
    public ViewerLayout currentLayout() {
        List<PlotSpec> specs = new ArrayList<>();
        plots.forEach(p -> specs.add(new PlotSpec(p.title(), p.entries())));
        return new ViewerLayout(specs, axis.windowMicros() / 1e6, legendVisible);
    }

    /** Every series some plot draws now, each once. */
    public List<Series> shownSeries() {
        Set<Series> all = new LinkedHashSet<>();
        plots.forEach(p -> all.addAll(p.plot().shownSeries()));
        return new ArrayList<>(all);
    }

    /** Frames painted by all plots. */
    public long framesPainted() {
        return plots.stream().mapToLong(p -> p.plot().frames()).sum();
    }

    @Override
    public void setFont(java.awt.Font font) {
        super.setFont(font);
        if (plots != null) {
            plots.forEach(p -> p.plot().setFont(font));
        }
    }
}
