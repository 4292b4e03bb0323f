package org.fdnet.hi.app;

import java.awt.BorderLayout;
import java.awt.Color;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.UIManager;

/** The line at the bottom: the last message (refusals and errors in red) and the network in numbers. */
public final class StatusBar extends JPanel {
    private static final Color ERROR = new Color(0xC0392B);
    private final JLabel message = new JLabel(" ");
    private final JLabel summary = new JLabel(" ");

    public StatusBar() {
        super(new BorderLayout());
        setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        message.setName("status.message");
        add(message, BorderLayout.CENTER);
        add(summary, BorderLayout.EAST);
    }

    public void info(String text) {
        message.setForeground(UIManager.getColor("Label.foreground"));
        message.setText(text);
    }

    public void error(String text) {
        message.setForeground(ERROR);
        message.setText(text);
    }

    public void summary(String text) {
        summary.setText(text);
    }

    public String message() {
        return message.getText();
    }
}
