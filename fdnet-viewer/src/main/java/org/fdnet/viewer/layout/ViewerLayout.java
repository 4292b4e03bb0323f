package org.fdnet.viewer.layout;

import java.util.List;

/**
 * What a viewer window shows, apart from the data: its plots (top to bottom) with their series, the width of the
 * shared time window, and whether the legends stand beside the plots. Read and written by {@link LayoutFile}.
 */
public record ViewerLayout(List<PlotSpec> plots, double windowSeconds, boolean legendVisible) {
    public ViewerLayout {
        plots = List.copyOf(plots);
        if (!(windowSeconds > 0)) {
            throw new IllegalArgumentException("the time window must be longer than 0 s, was " + windowSeconds);
        }
    }
}
