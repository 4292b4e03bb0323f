package org.fdnet.viewer.ui;

import java.awt.event.ActionEvent;
import java.io.IOException;
import java.util.List;
import javax.swing.AbstractAction;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.viewer.source.RunInfo;

/**
 * "Export…": opens the {@link ExportDialog} for the nodes selected in the window's list (or, when none is, the
 * plotted ones) and the time range of the plot on show.
 */
final class ExportAction extends AbstractAction {
    static final String NAME = "Export…";
    private final ViewerWindow window;

    ExportAction(ViewerWindow window) {
        super(NAME);
        putValue(SHORT_DESCRIPTION, "write the selected nodes' values in the visible time range as MCAP or CSV");
        this.window = window;
    }

    @Override
    public void actionPerformed(ActionEvent e) {
        List<LoggedNode> nodes = window.exportableNodes();
        if (nodes.isEmpty()) {
            window.showStatus("Export: select nodes in the list (or plot some) first");
            return;
        }
        RunInfo run = null;
        try {
            for (RunInfo r : window.connection().runs()) {
                if (r.nodes().stream().anyMatch(n -> n.sourceId() == nodes.get(0).sourceId())) {
                    run = r;
                }
            }
        } catch (IOException notListed) {
            window.showStatus("Export: the logger did not list its runs (" + notListed.getMessage() + "); exporting without");
        }
        PlotPanel plot = window.shownPlot();
        new ExportDialog(window, window.connection(), run, nodes, plot.viewStart(), plot.viewEnd()).setVisible(true);
    }
}
