package org.fdnet.viewer.ui;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.swing.DropMode;
import javax.swing.JTree;
import javax.swing.tree.DefaultMutableTreeNode;
import javax.swing.tree.DefaultTreeModel;
import javax.swing.tree.TreePath;
import javax.swing.tree.TreeSelectionModel;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.viewer.data.NodeSelection;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.data.Series;
import org.fdnet.viewer.data.UnitBook;
import org.fdnet.viewer.source.LoggerConnection;
import org.fdnet.viewer.source.RunInfo;

/**
 * The Datas of one recorded run as a tree: run → host → module → node → component (a Data holding several
 * numbers has one child per number, once its values are known). Names are shown whole, each level naming only
 * its own part. Chosen nodes or components are dragged into a plot ({@link SeriesTransfer}) or added with the
 * window's buttons.
 */
final class NodeTree extends JTree {
    private final UnitBook units;

    /** A tree row: the text shown, and the series it stands for (null for the run, a host or a module). */
    record Row(String text, NodeSelection selection) {
        @Override
        public String toString() {
            return text;
        }
    }

    NodeTree(UnitBook units) {
        super(new DefaultTreeModel(new DefaultMutableTreeNode(new Row("no run recorded yet", null))));
        this.units = units;
        setName("nodeTree");
        getSelectionModel().setSelectionMode(TreeSelectionModel.DISCONTIGUOUS_TREE_SELECTION);
        setDragEnabled(true);
        setDropMode(DropMode.ON);
        setTransferHandler(new SeriesTransfer.Drag(this::chosen));
        setToolTipText("drag Datas into a plot, or choose them and press Add to plot / New plot");
    }

    /** Shows the run's Datas; {@code data} tells how many components each has (none known: no component rows). */
    void show(RunInfo run, PlotData data) {
        DefaultMutableTreeNode root = new DefaultMutableTreeNode(new Row((run.network().isEmpty() ? "run" : run.network())
                + " (run " + run.runId() + ")", null));
        Map<String, Map<String, List<LoggedNode>>> byHost = new LinkedHashMap<>();
        for (LoggedNode n : run.nodesByHost()) {
            String host = run.hostOf(n).isEmpty() ? "this host" : run.hostOf(n);
            String module = n.name().module().isEmpty() ? "main" : n.name().module();
            byHost.computeIfAbsent(host, h -> new LinkedHashMap<>()).computeIfAbsent(module, m -> new ArrayList<>()).add(n);
        }
        byHost.forEach((host, modules) -> {
            DefaultMutableTreeNode h = new DefaultMutableTreeNode(new Row(host, null));
            root.add(h);
            modules.forEach((module, nodes) -> {
                DefaultMutableTreeNode m = new DefaultMutableTreeNode(new Row(module, null));
                h.add(m);
                for (LoggedNode n : nodes) {
                    String label = LoggerConnection.label(n);
                    String unit = units.unitOf(label, "");
                    DefaultMutableTreeNode node = new DefaultMutableTreeNode(new Row(n.name().node()
                            + (unit.isEmpty() ? "" : "  [" + unit + "]"), new NodeSelection(label, "")));
                    m.add(node);
                    List<Series> parts = data.seriesOf(n.sourceId());
                    if (parts.size() > 1) {
                        for (int i = 0; i < parts.size(); i++) {
                            String part = label + "[" + i + "]";
                            String partUnit = units.unitOf(part, "");
                            node.add(new DefaultMutableTreeNode(new Row("[" + i + "]"
                                    + (partUnit.isEmpty() ? "" : "  " + partUnit), new NodeSelection(part, ""))));
                        }
                    }
                }
            });
        });
        ((DefaultTreeModel) getModel()).setRoot(root);
        for (int row = 0; row < getRowCount(); row++) {
            TreePath p = getPathForRow(row);
            if (p.getPathCount() <= 3) {
                expandRow(row); // run, hosts and modules open; nodes closed
            }
        }
    }

    /** The nodes and components chosen (a module, host or run chosen stands for no series). */
    List<NodeSelection> chosen() {
        List<NodeSelection> out = new ArrayList<>();
        TreePath[] paths = getSelectionPaths();
        if (paths == null) {
            return out;
        }
        for (TreePath p : paths) {
            Object o = ((DefaultMutableTreeNode) p.getLastPathComponent()).getUserObject();
            if (o instanceof Row r && r.selection() != null) {
                out.add(r.selection());
            }
        }
        return out;
    }

    /** Chooses the rows of these series names (tests, scripted use); answers how many were found. */
    int choose(List<String> names) {
        clearSelection();
        int found = 0;
        for (int row = 0; row < getRowCount(); row++) {
            expandRow(row);
        }
        for (int row = 0; row < getRowCount(); row++) {
            Object o = ((DefaultMutableTreeNode) getPathForRow(row).getLastPathComponent()).getUserObject();
            if (o instanceof Row r && r.selection() != null && names.contains(r.selection().name())) {
                addSelectionRow(row);
                found++;
            }
        }
        return found;
    }
}
