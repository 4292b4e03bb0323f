package org.fdnet.hi.live;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.FlowLayout;
import java.awt.Window;
import javax.swing.BorderFactory;
import javax.swing.DefaultListCellRenderer;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import org.fdnet.control.NetworkDiff;
import org.fdnet.runtime.ChangeOutcome;

/**
 * Before pending changes reach a running network: every difference (added, removed and changed modules,
 * nodes and connections) listed, and one button that applies them all as one change request. Refused, the
 * dialog stays open with the reason and nothing changed on either side; Cancel keeps the changes pending.
 */
public final class DeployPreviewDialog extends JDialog {
    private static final Color ADDED = new Color(0x1A7F37);
    private static final Color REMOVED = new Color(0xC0392B);
    private static final Color CHANGED = new Color(0x9A6700);

    private final LiveSession session;
    private final JLabel outcome = new JLabel(" ");
    private ChangeOutcome result;

    private DeployPreviewDialog(Window owner, LiveSession session) {
        super(owner, "Deploy to " + session.name(), ModalityType.APPLICATION_MODAL);
        this.session = session;
        NetworkDiff diff = session.pending();
        JList<NetworkDiff.Entry> list = new JList<>(diff.entries().toArray(new NetworkDiff.Entry[0]));
        list.setName("deploy.entries");
        list.setCellRenderer(new EntryRenderer());
        list.setVisibleRowCount(Math.max(4, Math.min(16, diff.entries().size())));
        JLabel heading = new JLabel(diff.isEmpty() ? "No pending changes."
                : diff.entries().size() + " pending changes, applied to " + session.name() + " together or not at all:");
        heading.setBorder(BorderFactory.createEmptyBorder(8, 8, 4, 8));
        outcome.setName("deploy.outcome");
        outcome.setForeground(REMOVED);
        outcome.setBorder(BorderFactory.createEmptyBorder(4, 8, 0, 8));
        JButton apply = new JButton("Apply all");
        apply.setName("deploy.apply");
        apply.setEnabled(!diff.isEmpty());
        apply.addActionListener(e -> apply());
        JButton cancel = new JButton("Cancel");
        cancel.setName("deploy.cancel");
        cancel.addActionListener(e -> dispose());
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        buttons.add(apply);
        buttons.add(cancel);
        JPanel south = new JPanel(new BorderLayout());
        south.add(outcome, BorderLayout.NORTH);
        south.add(buttons, BorderLayout.SOUTH);
        add(heading, BorderLayout.NORTH);
        JScrollPane scroll = new JScrollPane(list);
        scroll.setBorder(BorderFactory.createCompoundBorder(BorderFactory.createEmptyBorder(0, 8, 0, 8), scroll.getBorder()));
        add(scroll, BorderLayout.CENTER);
        add(south, BorderLayout.SOUTH);
        getRootPane().setDefaultButton(apply);
        pack();
        setSize(Math.max(getWidth(), 560), getHeight());
        setLocationRelativeTo(owner);
    }

    /** Shows the preview (blocking until it closes); the outcome of Apply all, or {@code null} if not applied. */
    public static ChangeOutcome show(Window owner, LiveSession session) {
        DeployPreviewDialog dialog = new DeployPreviewDialog(owner, session);
        dialog.setVisible(true);
        return dialog.result;
    }

    private void apply() {
        ChangeOutcome o = session.deploy();
        result = o;
        if (o.executed()) {
            dispose();
        } else {
            outcome.setText("Refused, nothing applied: " + o.reason());
            pack();
        }
    }

    private static final class EntryRenderer extends DefaultListCellRenderer {
        @Override
        public Component getListCellRendererComponent(JList<?> list, Object value, int index, boolean selected, boolean focus) {
            NetworkDiff.Entry entry = (NetworkDiff.Entry) value;
            Component c = super.getListCellRendererComponent(list, entry.text(), index, selected, focus);
            if (!selected) {
                c.setForeground(switch (entry.change()) {
                    case ADDED -> ADDED;
                    case REMOVED -> REMOVED;
                    case CHANGED -> CHANGED;
                });
            }
            return c;
        }
    }
}
