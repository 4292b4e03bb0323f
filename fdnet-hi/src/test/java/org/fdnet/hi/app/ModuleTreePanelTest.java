package org.fdnet.hi.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Rectangle;
import java.awt.event.MouseEvent;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JButton;
import javax.swing.JTree;
import javax.swing.SwingUtilities;
import javax.swing.tree.DefaultMutableTreeNode;
import org.fdnet.hi.edit.UndoableNetworkEditor;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.xml.LayoutRepository;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.junit.jupiter.api.Test;

/** The module panel on networks/nested-arm.fdn, driven through its own components (no window needed). */
class ModuleTreePanelTest {
    private static final Path NESTED = Path.of("..", "networks", "nested-arm.fdn");

    private static GraphScene scene() throws Exception {
        return new GraphScene(new UndoableNetworkEditor(NetworkRepository.load(NESTED),
                LayoutRepository.load(LayoutRepository.sideFileOf(NESTED))));
    }

    private static List<String> rows(JTree tree) {
        List<String> rows = new ArrayList<>();
        for (int i = 0; i < tree.getRowCount(); i++) {
            DefaultMutableTreeNode node = (DefaultMutableTreeNode) tree.getPathForRow(i).getLastPathComponent();
            rows.add("  ".repeat(node.getLevel() - 1) + node.getUserObject());
        }
        return rows;
    }

    private static void click(JTree tree, int row) {
        Rectangle r = tree.getRowBounds(row);
        tree.dispatchEvent(new MouseEvent(tree, MouseEvent.MOUSE_CLICKED, System.currentTimeMillis(), 0,
                r.x + 5, r.y + r.height / 2, 1, false, MouseEvent.BUTTON1));
    }

    @Test
    void shouldShowModulesAsATreeWithNestedModulesBelowTheirParent() throws Exception {
        ModuleTreePanel panel = new ModuleTreePanel(scene());
        assertThat(rows(panel.tree())).containsExactly("main", "Arm", "  Arm/Hand", "    Arm/Hand/Fingers", "  Arm/Wrist");
    }

    @Test
    void shouldHideAndShowAWholeSubtreeWithOneClick() throws Exception {
        GraphScene scene = scene();
        ModuleTreePanel panel = new ModuleTreePanel(scene);
        SwingUtilities.invokeAndWait(() -> {
            panel.setSize(320, 400);
            panel.doLayout();
            panel.tree().setSize(panel.tree().getPreferredSize());
            click(panel.tree(), 2);
        });
        assertThat(scene.visible("Arm/Hand")).isFalse();
        assertThat(scene.visible("Arm/Hand/Fingers")).isFalse();
        assertThat(scene.visible("Arm")).isTrue();
        assertThat(scene.visible("Arm/Wrist")).isTrue();
        assertThat(scene.visibleNodes()).noneMatch(r -> r.module().startsWith("Arm/Hand"));
        SwingUtilities.invokeAndWait(() -> click(panel.tree(), 2));
        assertThat(scene.visible("Arm/Hand/Fingers")).isTrue();
    }

    @Test
    void shouldDisplayNoneAndDisplayAll() throws Exception {
        GraphScene scene = scene();
        ModuleTreePanel panel = new ModuleTreePanel(scene);
        JButton none = find(panel, "modules.none");
        JButton all = find(panel, "modules.all");
        SwingUtilities.invokeAndWait(none::doClick);
        assertThat(scene.network().modules()).extracting(ModuleInfo::name).noneMatch(scene::visible);
        assertThat(scene.visibleNodes()).isEmpty();
        SwingUtilities.invokeAndWait(all::doClick);
        assertThat(scene.network().modules()).extracting(ModuleInfo::name).allMatch(scene::visible);
    }

    private static JButton find(java.awt.Container c, String name) {
        for (java.awt.Component child : c.getComponents()) {
            if (name.equals(child.getName())) {
                return (JButton) child;
            }
            if (child instanceof java.awt.Container inner) {
                JButton found = find(inner, name);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }
}
