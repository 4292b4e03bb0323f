package org.fdnet.viewer.ui;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.util.ArrayList;
import java.util.List;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;
import org.fdnet.viewer.data.NodeSelection;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.data.Series;

/**
 * One plot of a {@link PlotGrid}: a header (title, unit, Split, Remove) over a {@link PlotPanel} that draws the
 * series of the nodes (or components) this plot holds. Series are dropped on it from the node tree
 * ({@link SeriesTransfer}); the grid decides whether their unit fits.
 *
 * <p>Component names (for tests): {@code plotTitle}, {@code splitPlot}, {@code removePlot}.
 */
public final class PlotView extends JPanel {
    private final List<NodeSelection> entries = new ArrayList<>();
    private final PlotPanel plot;
    private final JLabel title = new JLabel();
    private String name;
    private String unit = "";

    PlotView(String name, PlotGrid grid, PlotData data, TimeAxis axis) {
        super(new BorderLayout());
        this.name = name;
        plot = new PlotPanel(data, axis, this::chosen);
        plot.setPreferredSize(new java.awt.Dimension(600, 140));
        title.setName("plotTitle");
        JButton split = new JButton("Split");
        split.setName("splitPlot");
        split.setToolTipText("add an empty plot below this one, on the same time axis");
        split.addActionListener(e -> grid.addAfter(this, "plot " + (grid.plots().size() + 1)));
        JButton remove = new JButton("Remove");
        remove.setName("removePlot");
        remove.setToolTipText("remove this plot (its series stay in the tree)");
        remove.addActionListener(e -> grid.removePlot(this));
        split.putClientProperty("JButton.buttonType", "toolBarButton");
        remove.putClientProperty("JButton.buttonType", "toolBarButton");
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT, 2, 0));
        buttons.setOpaque(false);
        buttons.add(split);
        buttons.add(remove);
        JPanel header = new JPanel(new BorderLayout());
        header.setBorder(BorderFactory.createEmptyBorder(1, 6, 1, 2));
        header.add(title, BorderLayout.CENTER);
        header.add(buttons, BorderLayout.EAST);
        add(header, BorderLayout.NORTH);
        add(plot, BorderLayout.CENTER);
        setBorder(BorderFactory.createMatteBorder(0, 0, 1, 0, new java.awt.Color(0xc8, 0xcc, 0xd2)));
        setTransferHandler(new SeriesTransfer.Drop(selections -> grid.addSeries(this, selections)));
        plot.setTransferHandler(getTransferHandler());
        showTitle();
    }

    private List<Series> chosen(PlotData data) {
        List<Series> out = new ArrayList<>();
        for (Series s : data.series()) {
            for (NodeSelection e : entries) {
                if (e.matches(s)) {
                    out.add(s);
                    break;
                }
            }
        }
        return out;
    }

    public PlotPanel plot() {
        return plot;
    }

    public String title() {
        return name;
    }

    /** The unit of the series it holds ({@code ""}: none, or empty). */
    public String unit() {
        return unit;
    }

    /** The nodes and components it holds, each with its unit. */
    public List<NodeSelection> entries() {
        return List.copyOf(entries);
    }

    boolean holds(NodeSelection s) {
        return entries.stream().anyMatch(e -> e.name().equals(s.name()));
    }

    void addEntry(NodeSelection s) {
        if (entries.isEmpty()) {
            unit = s.unit();
        }
        entries.add(s);
        showTitle();
    }

    private void showTitle() {
        title.setText(name + (entries.isEmpty() ? "  (empty: drag Datas here)" : unit.isEmpty() ? "" : "  ·  " + unit));
    }
}
