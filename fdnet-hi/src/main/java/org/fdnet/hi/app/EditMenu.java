package org.fdnet.hi.app;

import java.awt.Point;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import javax.swing.Action;
import javax.swing.JComponent;
import javax.swing.JMenu;
import javax.swing.JOptionPane;
import javax.swing.JPopupMenu;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.edit.UndoableNetworkEditor;
import org.fdnet.hi.graph.ConnectionRef;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.hi.merge.MergeReplaceDialog;
import org.fdnet.hi.text.AdvancedModuleFrame;
import org.fdnet.hi.text.BasicModuleFrame;
import org.fdnet.hi.text.NetworkFrame;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * Edit: undo, redo, find, and the graphic panel's edits of the network — add a Data or Relation, connect two
 * nodes, rename, delete, merge or replace. Every edit goes through the {@link UndoableNetworkEditor}; a refusal
 * shows in the status bar and changes nothing.
 */
final class EditMenu {
    private final HiWindow window;
    private final JMenu menu = new JMenu("Edit");
    private final Action undo;
    private final Action redo;
    private final List<Action> editing = new ArrayList<>();

    EditMenu(HiWindow window) {
        this.window = window;
        menu.setName("menu.edit");
        undo = MenuItems.action("Undo", "control Z", () -> report(editor().undo(), "Undone"));
        redo = MenuItems.action("Redo", "control Y", () -> report(editor().redo(), "Redone"));
        menu.add(undo);
        menu.add(redo);
        menu.addSeparator();
        menu.add(editing(MenuItems.action("Find…", "control F", () -> window.search().open())));
        menu.addSeparator();
        menu.add(editing(MenuItems.action("Network…", "control shift N", () -> openNetworkFrame())));
        menu.add(editing(MenuItems.action("Module…", "control shift M", () -> openModuleFrame(false))));
        menu.add(editing(MenuItems.action("Module (Advanced)…", "control shift E", () -> openModuleFrame(true))));
        menu.addSeparator();
        menu.add(editing(MenuItems.action("Add Data…", null, () -> addNode(NodeKind.DATA))));
        menu.add(editing(MenuItems.action("Add Relation…", null, () -> addNode(NodeKind.RELATION))));
        menu.add(editing(MenuItems.action("Connect Selected Nodes", "control K", this::connectSelected)));
        menu.add(editing(MenuItems.action("Rename Node…", "F2", this::renameSelected)));
        menu.add(editing(MenuItems.action("Merge or Replace Selected Nodes…", "control M", this::mergeSelected)));
        menu.add(editing(MenuItems.action("Delete", "DELETE", this::deleteSelected)));
    }

    JMenu menu() {
        return menu;
    }

    void refresh() {
        boolean open = window.current() != null;
        undo.setEnabled(open && editor().canUndo());
        redo.setEnabled(open && editor().canRedo());
        undo.putValue(Action.NAME, open && editor().canUndo() ? "Undo " + editor().undoLabel() : "Undo");
        redo.putValue(Action.NAME, open && editor().canRedo() ? "Redo " + editor().redoLabel() : "Redo");
        editing.forEach(a -> a.setEnabled(open));
    }

    /** Double-click on a node: the Advanced Module frame of its module, with the node loaded. */
    void openNode(NodeRef ref) {
        scene().select(Set.of(ref));
        AdvancedModuleFrame.open(window, editor(), ref.module()).showNode(ref.node());
    }

    /** The thesis's Network frame: modules, load at start, the network in numbers. */
    javax.swing.JDialog openNetworkFrame() {
        return NetworkFrame.open(window, editor());
    }

    /** The Basic or Advanced Module frame of the selected node's module (main when nothing is selected). */
    javax.swing.JDialog openModuleFrame(boolean advanced) {
        String module = selectedModule();
        if (advanced) {
            AdvancedModuleFrame frame = AdvancedModuleFrame.open(window, editor(), module);
            if (scene().selection().size() == 1) {
                frame.showNode(scene().selection().iterator().next().node());
            }
            return frame;
        }
        return BasicModuleFrame.open(window, editor(), module);
    }

    void popup(JComponent canvas, Point p, NodeRef ref) {
        JPopupMenu popup = new JPopupMenu();
        if (ref != null) {
            popup.add(MenuItems.action("Highlight Ancestors", null, () -> scene().highlight(ref, GraphScene.Relatives.ANCESTORS)));
            popup.add(MenuItems.action("Highlight Descendants", null, () -> scene().highlight(ref, GraphScene.Relatives.DESCENDANTS)));
            popup.add(MenuItems.action("Highlight Both", null, () -> scene().highlight(ref, GraphScene.Relatives.BOTH)));
            popup.add(MenuItems.action("Clear Highlight", null, () -> scene().highlight(null, GraphScene.Relatives.BOTH)));
            popup.addSeparator();
            popup.add(MenuItems.action("Node Colour…", null, () -> ViewMenu.chooseNodeColour(window)));
            popup.add(MenuItems.action("Node Size…", null, () -> ViewMenu.chooseNodeSize(window)));
            popup.addSeparator();
            popup.add(MenuItems.action("Rename…", null, this::renameSelected));
            popup.add(MenuItems.action("Merge or Replace…", null, this::mergeSelected));
            popup.add(MenuItems.action("Delete", null, this::deleteSelected));
        } else {
            popup.add(MenuItems.action("Add Data…", null, () -> addNode(NodeKind.DATA)));
            popup.add(MenuItems.action("Add Relation…", null, () -> addNode(NodeKind.RELATION)));
            popup.add(MenuItems.action("Fit to Window", null, () -> window.canvas().fit()));
        }
        popup.show(canvas, p.x, p.y);
    }

    private Action editing(Action a) {
        editing.add(a);
        return a;
    }

    private UndoableNetworkEditor editor() {
        return window.current().editor();
    }

    private GraphScene scene() {
        return window.current().scene();
    }

    private void report(EditResult result, String done) {
        if (result.accepted()) {
            window.status().info(done);
        }
    }

    private void addNode(NodeKind kind) {
        List<String> modules = new ArrayList<>();
        for (ModuleInfo m : editor().network().modules()) {
            modules.add(m.name());
        }
        NodeDraft draft = NodeDraft.ask(window, kind, modules, selectedModule());
        if (draft == null) {
            return;
        }
        NodeInfo node = new NodeInfo(kind, draft.name(), "localhost", "", draft.className(), List.of());
        EditResult r = editor().addNode(draft.module(), node);
        if (r.accepted()) {
            scene().select(Set.of(r.node()));
            window.canvas().reveal(r.node());
            window.status().info("Added " + kind.label() + " " + r.node());
        }
    }

    private String selectedModule() {
        return scene().selection().isEmpty() ? ModuleInfo.MAIN : scene().selection().iterator().next().module();
    }

    /** Two selected nodes, one Data and one Relation: a Reader (Data first) or a Writer (Relation first). */
    private void connectSelected() {
        List<NodeRef> two = new ArrayList<>(scene().selection());
        if (two.size() != 2) {
            window.status().error("Select a Data and a Relation to connect (Data first: Reader; Relation first: Writer)");
            return;
        }
        NodeRef first = two.get(0);
        NodeRef second = two.get(1);
        boolean firstIsData = editor().network().node(first).kind() == NodeKind.DATA;
        ConnectionInfo c = firstIsData ? ConnectionInfo.reader(first, second) : ConnectionInfo.writer(first, second);
        String module = firstIsData ? second.module() : first.module();
        EditResult r = editor().addConnection(module, c);
        if (r.accepted()) {
            scene().selectConnection(new ConnectionRef(module, c));
            window.status().info("Added " + c);
        }
    }

    private void renameSelected() {
        if (scene().selection().size() != 1) {
            window.status().error("Select one node to rename");
            return;
        }
        NodeRef ref = scene().selection().iterator().next();
        String name = JOptionPane.showInputDialog(window, "New name for " + ref + ":", ref.node());
        if (name != null) {
            EditResult r = MergeReplaceDialog.renameOrAsk(window, editor(), ref, name.trim());
            window.canvas().requestFocus();
            if (r != null && r.accepted()) {
                scene().select(Set.of(r.node()));
                window.status().info("Renamed " + ref + " to " + name.trim());
            }
        }
    }

    private void mergeSelected() {
        List<NodeRef> two = new ArrayList<>(scene().selection());
        if (two.size() != 2) {
            window.status().error("Select the two nodes to merge or replace (the first selected stays)");
            return;
        }
        if (two.get(0).module().equals(two.get(1).module())) {
            mergeInOneModule(two.get(0), two.get(1));
            return;
        }
        CrossModuleMerge.Options offered = CrossModuleMerge.possible(editor().network(), two.get(0), two.get(1));
        if (offered.choices().isEmpty()) {
            window.status().error("Cannot make " + two.get(0) + " and " + two.get(1) + " one node: " + offered.whyNone());
            return;
        }
        CrossModuleMerge choice = CrossModuleMerge.ask(window, two.get(0), two.get(1), offered.choices());
        window.canvas().requestFocus();
        if (choice == null) {
            return;
        }
        EditResult r = choice.replace() ? editor().replaceNode(two.get(1), two.get(0))
                : editor().mergeNodes(two.get(0), two.get(1), choice.policy());
        if (r.accepted()) {
            scene().select(Set.of(r.node()));
            window.status().info((choice.replace() ? "Replaced " : "Merged into ") + r.node());
        }
    }

    /**
     * Two nodes of one module: the thesis's Merge/Replace dialog, as if the second took the first's name
     * (replace: the first goes; merge: the first stays, with every connection of both).
     */
    private void mergeInOneModule(NodeRef stays, NodeRef incoming) {
        MergeReplaceDialog dialog = new MergeReplaceDialog(window, editor(), incoming, stays.node());
        dialog.setVisible(true);
        window.canvas().requestFocus();
        EditResult r = dialog.result();
        if (r != null && r.accepted()) {
            scene().select(Set.of(r.node() != null ? r.node() : stays));
            window.status().info("Merged or replaced: " + stays);
        }
    }

    private void deleteSelected() {
        ConnectionRef c = scene().selectedConnection();
        if (c != null) {
            if (editor().deleteConnection(c.module(), c.connection()).accepted()) {
                window.status().info("Deleted " + c.connection());
            }
            return;
        }
        for (NodeRef ref : new ArrayList<>(scene().selection())) {
            if (editor().deleteNode(ref).accepted()) {
                window.status().info("Deleted " + ref + " and its connections");
            }
        }
    }
}
