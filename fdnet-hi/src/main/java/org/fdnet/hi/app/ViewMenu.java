package org.fdnet.hi.app;

import java.awt.Color;
import java.awt.GridLayout;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.List;
import javax.swing.Action;
import javax.swing.JColorChooser;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JSpinner;
import javax.swing.SpinnerNumberModel;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NodeRef;

/** View: zoom, fit, automatic layout, highlighting relatives, colours and sizes — the .fdg side only, never the network. */
final class ViewMenu {
    private final HiWindow window;
    private final JMenu menu = new JMenu("View");
    private final List<Action> actions = new ArrayList<>();

    ViewMenu(HiWindow window) {
        this.window = window;
        menu.setName("menu.view");
        menu.add(add(MenuItems.action("Fit to Window", "control 0", () -> window.canvas().fit())));
        menu.add(add(MenuItems.action("Zoom In", "control EQUALS", () -> window.canvas().setZoom(window.canvas().zoom() * 1.25))));
        menu.add(add(MenuItems.action("Zoom Out", "control MINUS", () -> window.canvas().setZoom(window.canvas().zoom() / 1.25))));
        menu.add(add(MenuItems.action("Lay Out Again (ELK)", "control L", this::relayout)));
        menu.addSeparator();
        menu.add(add(MenuItems.action("Highlight Ancestors", "control shift A", () -> highlight(GraphScene.Relatives.ANCESTORS))));
        menu.add(add(MenuItems.action("Highlight Descendants", "control shift D", () -> highlight(GraphScene.Relatives.DESCENDANTS))));
        menu.add(add(MenuItems.action("Highlight Both", "control shift B", () -> highlight(GraphScene.Relatives.BOTH))));
        menu.add(add(MenuItems.action("Clear Highlight", "ESCAPE", () -> window.current().scene().highlight(null, GraphScene.Relatives.BOTH))));
        menu.addSeparator();
        menu.add(add(MenuItems.action("Node Colour…", null, () -> chooseNodeColour(window))));
        menu.add(add(MenuItems.action("Node Size…", null, () -> chooseNodeSize(window))));
        menu.add(add(MenuItems.action("Module Colour…", null, this::chooseModuleColour)));
        menu.add(add(MenuItems.action("Show All Modules", null, () -> showAll(true))));
        menu.add(add(MenuItems.action("Hide All Modules (Display None)", null, () -> showAll(false))));
    }

    JMenu menu() {
        return menu;
    }

    void refresh() {
        actions.forEach(a -> a.setEnabled(window.current() != null));
    }

    private Action add(Action a) {
        actions.add(a);
        return a;
    }

    private void relayout() {
        long start = System.nanoTime();
        window.current().scene().relayoutAll();
        window.canvas().fit();
        window.status().info(String.format("Laid out again with ELK layered in %.0f ms", (System.nanoTime() - start) / 1e6));
    }

    private void highlight(GraphScene.Relatives which) {
        GraphScene scene = window.current().scene();
        if (scene.selection().size() != 1) {
            window.status().error("Select one node to highlight its relatives");
            return;
        }
        NodeRef ref = scene.selection().iterator().next();
        scene.highlight(ref, which);
        window.status().info(scene.highlighted().size() - 1 + " " + which.name().toLowerCase() + " of " + ref + " highlighted");
    }

    static void chooseNodeColour(HiWindow window) {
        GraphScene scene = window.current().scene();
        if (scene.selection().isEmpty()) {
            window.status().error("Select the nodes to colour");
            return;
        }
        NodeRef first = scene.selection().iterator().next();
        Color c = JColorChooser.showDialog(window, "Node colour", scene.fillColour(first));
        if (c != null) {
            for (NodeRef ref : scene.selection()) {
                scene.setNodeColour(ref, c);
            }
        }
    }

    static void chooseNodeSize(HiWindow window) {
        GraphScene scene = window.current().scene();
        if (scene.selection().isEmpty()) {
            window.status().error("Select the nodes to size");
            return;
        }
        Rectangle2D b = scene.bounds(scene.selection().iterator().next());
        JSpinner w = new JSpinner(new SpinnerNumberModel(b.getWidth(), 20, 1000, 10));
        JSpinner h = new JSpinner(new SpinnerNumberModel(b.getHeight(), 16, 600, 4));
        JPanel form = new JPanel(new GridLayout(0, 2, 6, 4));
        form.add(new JLabel("Width"));
        form.add(w);
        form.add(new JLabel("Height"));
        form.add(h);
        if (JOptionPane.showConfirmDialog(window, form, "Node size", JOptionPane.OK_CANCEL_OPTION,
                JOptionPane.PLAIN_MESSAGE) == JOptionPane.OK_OPTION) {
            for (NodeRef ref : scene.selection()) {
                scene.setNodeSize(ref, (Double) w.getValue(), (Double) h.getValue());
            }
        }
    }

    private void chooseModuleColour() {
        GraphScene scene = window.current().scene();
        List<String> modules = new ArrayList<>();
        for (ModuleInfo m : scene.network().modules()) {
            modules.add(m.name());
        }
        JComboBox<String> box = new JComboBox<>(modules.toArray(String[]::new));
        if (JOptionPane.showConfirmDialog(window, box, "Module", JOptionPane.OK_CANCEL_OPTION) != JOptionPane.OK_OPTION) {
            return;
        }
        String module = (String) box.getSelectedItem();
        Color c = JColorChooser.showDialog(window, "Colour of module " + module, scene.moduleColour(module));
        if (c != null) {
            scene.setModuleColour(module, c);
        }
    }

    private void showAll(boolean show) {
        window.current().scene().setAllModulesVisible(show);
    }
}
