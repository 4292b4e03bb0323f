package org.fdnet.hi.app;

import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.FlowLayout;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.util.HashMap;
import java.util.Map;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JPanel;
import javax.swing.JTree;
import javax.swing.tree.DefaultMutableTreeNode;
import javax.swing.tree.DefaultTreeModel;
import javax.swing.tree.TreeCellRenderer;
import javax.swing.tree.TreePath;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.hi.graph.SceneListener;
import org.fdnet.netinfo.ModuleInfo;

/**
 * The module panel (thesis Figure 36, "Display all / Display none"): the network's modules as a tree, nested
 * modules below their parent, each with a check box that shows or hides it in the graph. Clicking a module shows or
 * hides it together with every module inside it; <em>Display all</em> and <em>Display none</em> show or hide every
 * module. Component names (for tests): {@code modules.tree}, {@code modules.all}, {@code modules.none}.
 */
public final class ModuleTreePanel extends JPanel implements SceneListener {
    private final GraphScene scene;
    private final JTree tree = new JTree(new DefaultTreeModel(new DefaultMutableTreeNode("modules")));
    private String shown = "";

    public ModuleTreePanel(GraphScene scene) {
        super(new BorderLayout());
        this.scene = scene;
        setBorder(BorderFactory.createTitledBorder("Modules"));
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        buttons.add(button("Display all", "modules.all", () -> showAll(true)));
        buttons.add(button("Display none", "modules.none", () -> showAll(false)));
        add(buttons, BorderLayout.NORTH);
        tree.setName("modules.tree");
        tree.setRootVisible(false);
        tree.setShowsRootHandles(true);
        tree.setCellRenderer(new VisibilityRenderer());
        tree.addMouseListener(new MouseAdapter() {
            @Override
            public void mouseClicked(MouseEvent e) {
                TreePath path = tree.getPathForLocation(e.getX(), e.getY());
                if (path != null) {
                    toggleSubtree((String) ((DefaultMutableTreeNode) path.getLastPathComponent()).getUserObject());
                }
            }
        });
        add(tree, BorderLayout.CENTER);
        scene.addListener(this);
        rebuild();
    }

    private static JButton button(String text, String name, Runnable action) {
        JButton b = new JButton(text);
        b.setName(name);
        b.addActionListener(e -> action.run());
        return b;
    }

    /** Shows {@code module} and every module inside it when it is hidden; hides them all when it is shown. */
    public void toggleSubtree(String module) {
        scene.setModuleSubtreeVisible(module, !scene.visible(module));
    }

    /** Display all ({@code true}) or Display none ({@code false}). */
    public void showAll(boolean show) {
        scene.setAllModulesVisible(show);
    }

    public JTree tree() {
        return tree;
    }

    @Override
    public void sceneChanged() {
        rebuild();
    }

    @Override
    public void selectionChanged() {
        // the panel does not show the selection
    }

    private void rebuild() {
        String key = scene.modulesKey();
        if (key.equals(shown)) {
            tree.repaint();
            return;
        }
        shown = key;
        DefaultMutableTreeNode root = new DefaultMutableTreeNode("modules");
        Map<String, DefaultMutableTreeNode> nodes = new HashMap<>();
        for (ModuleInfo m : scene.network().modules()) {
            DefaultMutableTreeNode node = new DefaultMutableTreeNode(m.name());
            nodes.put(m.name(), node);
            String parent = m.parentName();
            (parent == null ? root : nodes.get(parent)).add(node);
        }
        tree.setModel(new DefaultTreeModel(root));
        for (int row = 0; row < tree.getRowCount(); row++) {
            tree.expandRow(row);
        }
    }

    /** A check box with the module's own name, in its colour, ticked when the module is shown. */
    private final class VisibilityRenderer implements TreeCellRenderer {
        private final JCheckBox box = new JCheckBox();

        @Override
        public Component getTreeCellRendererComponent(JTree t, Object value, boolean selected, boolean expanded,
                                                      boolean leaf, int row, boolean hasFocus) {
            Object module = ((DefaultMutableTreeNode) value).getUserObject();
            String path = String.valueOf(module);
            box.setText(path.substring(path.lastIndexOf('/') + 1));
            box.setOpaque(false);
            box.setSelected(scene.visible(path));
            box.setForeground(scene.moduleColour(path).darker());
            box.setToolTipText((scene.visible(path) ? "Hide " : "Show ") + "module " + path + " and the modules inside it");
            return box;
        }
    }
}
