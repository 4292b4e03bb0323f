package org.fdnet.viewer.ui;

import java.awt.FlowLayout;
import java.util.LinkedHashMap;
import java.util.Map;
import javax.swing.AbstractButton;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JPanel;
import javax.swing.JSeparator;
import javax.swing.SwingConstants;

/**
 * The viewer's tool bar: its actions in the order they were added, each a named button (or a control of its own)
 * with a tooltip. {@link ViewerWindow} registers them all in one method; a new action is one more {@link #add}.
 */
final class ViewerActions {
    private final Map<String, JComponent> controls = new LinkedHashMap<>();
    private final JPanel bar = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 3));
    private int gaps;

    ViewerActions() {
        bar.setName("toolBar");
        bar.setBorder(BorderFactory.createEmptyBorder(1, 2, 1, 2));
    }

    /** A button named {@code name} (its component name too) that runs {@code action}. */
    JButton add(String name, String text, String tooltip, Runnable action) {
        JButton b = new JButton(text);
        b.addActionListener(e -> action.run());
        b.setName(name);
        add(b, tooltip);
        return b;
    }

    /** A control of its own (a toggle, a field), named by its component name. */
    void add(JComponent control, String tooltip) {
        control.setToolTipText(tooltip);
        if (control instanceof AbstractButton b) {
            b.setFocusable(false);
        }
        controls.put(control.getName(), control);
        bar.add(control);
    }

    /** A separator between groups of actions. */
    void gap() {
        JSeparator s = new JSeparator(SwingConstants.VERTICAL);
        s.setPreferredSize(new java.awt.Dimension(6, 22));
        s.setName("gap" + ++gaps);
        bar.add(s);
    }

    /** The control registered under that name. */
    JComponent control(String name) {
        return controls.get(name);
    }

    JPanel toolBar() {
        return bar;
    }
}
