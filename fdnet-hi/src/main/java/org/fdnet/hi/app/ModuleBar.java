package org.fdnet.hi.app;

import java.awt.Color;
import java.awt.Component;
import java.awt.FlowLayout;
import java.awt.Graphics;
import javax.swing.Icon;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JToggleButton;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.hi.graph.SceneListener;
import org.fdnet.netinfo.ModuleInfo;

/** One toggle per module, in the module's colour: one click shows or hides the module in the graph. */
public final class ModuleBar extends JPanel implements SceneListener {
    private final GraphScene scene;
    private String shown = "";

    public ModuleBar(GraphScene scene) {
        super(new FlowLayout(FlowLayout.LEFT, 4, 2));
        this.scene = scene;
        scene.addListener(this);
        rebuild();
    }

    @Override
    public void sceneChanged() {
        rebuild();
    }

    @Override
    public void selectionChanged() {
        // the bar does not show the selection
    }

    private void rebuild() {
        String key = scene.modulesKey();
        if (key.equals(shown)) {
            return;
        }
        shown = key;
        removeAll();
        add(new JLabel("Modules:"));
        for (ModuleInfo m : scene.network().modules()) {
            String module = m.name();
            JToggleButton b = new JToggleButton(module, new Swatch(scene.moduleColour(module)), scene.visible(module));
            b.setName("module." + module);
            b.setToolTipText((scene.visible(module) ? "Hide " : "Show ") + "module " + module);
            b.addActionListener(e -> scene.setModuleVisible(module, b.isSelected()));
            add(b);
        }
        revalidate();
        repaint();
    }

    /** A small square of the module's colour. */
    private record Swatch(Color colour) implements Icon {
        @Override
        public void paintIcon(Component c, Graphics g, int x, int y) {
            g.setColor(colour);
            g.fillRoundRect(x, y, 12, 12, 4, 4);
        }

        @Override
        public int getIconWidth() {
            return 12;
        }

        @Override
        public int getIconHeight() {
            return 12;
        }
    }
}
