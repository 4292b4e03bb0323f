package org.fdnet.viewer.layout;

import java.util.List;
import org.fdnet.viewer.data.NodeSelection;

/** One plot of a layout: its title and the series it holds (a node, or one component of it, each with its unit). */
public record PlotSpec(String title, List<NodeSelection> series) {
    public PlotSpec {
        series = List.copyOf(series);
    }
}
