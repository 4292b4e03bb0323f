package org.fdnet.hi.app;

import java.awt.FlowLayout;
import java.util.List;
import java.util.Set;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import org.fdnet.hi.graph.GraphCanvas;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.netinfo.NodeRef;

/**
 * Ctrl-F: find nodes by name, class or parameter. Enter (or Next) goes to the next match: its module is
 * shown if hidden, the node is selected and the panel scrolls to it.
 */
public final class SearchBar extends JPanel {
    private final GraphScene scene;
    private final GraphCanvas canvas;
    private final JTextField field = new JTextField(24);
    private final JLabel result = new JLabel(" ");
    private int next;
    private String lastText = "";

    public SearchBar(GraphScene scene, GraphCanvas canvas) {
        super(new FlowLayout(FlowLayout.LEFT, 6, 2));
        this.scene = scene;
        this.canvas = canvas;
        field.setName("search.field");
        field.putClientProperty("JTextField.placeholderText", "name, class or parameter");
        JButton nextButton = new JButton("Next");
        JButton close = new JButton("✕");
        field.addActionListener(e -> findNext());
        nextButton.addActionListener(e -> findNext());
        close.addActionListener(e -> setVisible(false));
        add(new JLabel("Find:"));
        add(field);
        add(nextButton);
        add(result);
        add(close);
        setVisible(false);
    }

    public void open() {
        setVisible(true);
        field.selectAll();
        field.requestFocusInWindow();
    }

    public void search(String text) {
        field.setText(text);
        findNext();
    }

    /** Selects and reveals the next match; returns it, or {@code null}. */
    public NodeRef findNext() {
        String text = field.getText();
        List<NodeRef> hits = NodeSearch.find(scene.network(), text);
        if (!text.equals(lastText)) {
            next = 0;
            lastText = text;
        }
        if (hits.isEmpty()) {
            result.setText(text.isBlank() ? " " : "no match");
            return null;
        }
        NodeRef hit = hits.get(next % hits.size());
        result.setText((next % hits.size() + 1) + " of " + hits.size());
        next++;
        if (!scene.visible(hit.module())) {
            scene.setModuleVisible(hit.module(), true);
        }
        scene.select(Set.of(hit));
        canvas.reveal(hit);
        return hit;
    }
}
