package org.fdnet.viewer.ui;

import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.StringSelection;
import java.awt.datatransfer.Transferable;
import java.awt.datatransfer.UnsupportedFlavorException;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import java.util.function.ToIntFunction;
import javax.swing.JComponent;
import javax.swing.TransferHandler;
import org.fdnet.viewer.data.NodeSelection;

/**
 * Dragging series from the node tree into a plot: the tree exports the chosen nodes as text, one
 * {@code Module/Node[unit]} (or {@code Module/Node[i][unit]}) per line; a plot imports such text. Text dragged
 * from elsewhere in that form is taken too.
 */
final class SeriesTransfer {
    private SeriesTransfer() {
    }

    static String text(List<NodeSelection> selections) {
        StringBuilder b = new StringBuilder();
        selections.forEach(s -> b.append(s).append('\n'));
        return b.toString();
    }

    static List<NodeSelection> parse(String text) {
        List<NodeSelection> out = new ArrayList<>();
        for (String line : text.split("\n")) {
            if (!line.isBlank()) {
                out.add(NodeSelection.parse(line));
            }
        }
        return out;
    }

    /** The tree's side: exports the selections it is given at the start of a drag. */
    static final class Drag extends TransferHandler {
        private final Supplier<List<NodeSelection>> chosen;

        Drag(Supplier<List<NodeSelection>> chosen) {
            this.chosen = chosen;
        }

        @Override
        public int getSourceActions(JComponent c) {
            return COPY;
        }

        @Override
        protected Transferable createTransferable(JComponent c) {
            List<NodeSelection> s = chosen.get();
            return s.isEmpty() ? null : new StringSelection(text(s));
        }
    }

    /** A plot's side: hands the dropped selections to {@code accept}, which answers how many it took. */
    static final class Drop extends TransferHandler {
        private final ToIntFunction<List<NodeSelection>> accept;

        Drop(ToIntFunction<List<NodeSelection>> accept) {
            this.accept = accept;
        }

        @Override
        public boolean canImport(TransferSupport support) {
            return support.isDataFlavorSupported(DataFlavor.stringFlavor);
        }

        @Override
        public boolean importData(TransferSupport support) {
            if (!canImport(support)) {
                return false;
            }
            try {
                String text = (String) support.getTransferable().getTransferData(DataFlavor.stringFlavor);
                return accept.applyAsInt(parse(text)) > 0;
            } catch (UnsupportedFlavorException | IOException | IllegalArgumentException e) {
                return false;
            }
        }
    }
}
