package org.fdnet.viewer.ui;

import java.util.List;
import org.fdnet.event.wire.LoggedNode;

/**
 * "Export…": opens the {@link ExportDialog} for the Datas chosen in the window's tree (or, when none is, the plotted
 * ones) of the run chosen on the left, and the plots' visible time range.
 */
final class ExportAction implements Runnable {
    static final String NAME = "Export…";
    static final String TOOLTIP = "the chosen (else plotted) Datas' values in the visible time range as MCAP or CSV";
    private final ViewerWindow window;

    ExportAction(ViewerWindow window) {
        this.window = window;
    }

    @Override
    public void run() {
        List<LoggedNode> nodes = window.exportableNodes();
        if (nodes.isEmpty()) {
            window.showStatus("Export: choose a run on the left and Datas in its tree (or plot some) first");
            return;
        }
        TimeAxis axis = window.plots().axis();
        new ExportDialog(window, window.connection(), window.exportRun(), nodes, axis.viewStart(), axis.viewEnd())
                .setVisible(true);
    }
}
