package org.fdnet.hi.merge;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.GridLayout;
import java.awt.Window;
import java.util.EnumMap;
import java.util.Map;

import javax.swing.BorderFactory;
import javax.swing.ButtonGroup;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JRadioButton;
import javax.swing.WindowConstants;

import org.fdnet.hi.edit.NetworkEditor;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.netinfo.MergePolicy;
import org.fdnet.netinfo.NodeRef;

/**
 * The thin Swing view of {@link MergeReplaceChoice}: a modal dialog asking whether the node taking a used name
 * replaces the node that has it or merges with it, and which parameters a merge keeps. OK applies the choice
 * through the editor; a refusal is shown in the dialog, which stays open; Cancel changes nothing.
 */
public final class MergeReplaceDialog extends JDialog {
    private final MergeReplaceChoice choice;
    private final JRadioButton replace = new JRadioButton("Replace");
    private final JRadioButton merge = new JRadioButton("Merge");
    private final Map<MergePolicy, JRadioButton> policies = new EnumMap<>(MergePolicy.class);
    private final JLabel status = new JLabel(" ");
    private final JButton ok = new JButton("OK");
    private final JButton cancel = new JButton("Cancel");
    private EditResult result;

    public MergeReplaceDialog(Window owner, NetworkEditor editor, NodeRef incoming, String takenName) {
        super(owner, "Name already used", ModalityType.APPLICATION_MODAL);
        this.choice = new MergeReplaceChoice(editor, incoming, takenName);
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);

        JPanel body = new JPanel(new GridLayout(0, 1, 4, 4));
        body.setBorder(BorderFactory.createEmptyBorder(10, 12, 6, 12));
        body.add(new JLabel("Module '" + incoming.module() + "' already has a node named '" + takenName + "'."));
        body.add(new JLabel("What should " + incoming + " do with " + choice.existing() + "?"));
        ButtonGroup actions = new ButtonGroup();
        replace.setToolTipText(choice.existing() + " and its connections go; " + incoming
                + " takes its name with its own connections");
        merge.setToolTipText("one node remains, named '" + takenName + "', with every connection of both");
        actions.add(replace);
        actions.add(merge);
        body.add(replace);
        body.add(new JLabel("      " + choice.existing() + " and its connections go; " + incoming.node()
                + " takes the name and keeps its own connections"));
        body.add(merge);
        ButtonGroup policyGroup = new ButtonGroup();
        for (MergePolicy p : MergePolicy.values()) {
            JRadioButton b = new JRadioButton("Keep " + choice.describe(p));
            b.setBorder(BorderFactory.createEmptyBorder(0, 24, 0, 0));
            policies.put(p, b);
            policyGroup.add(b);
            body.add(b);
        }
        policies.get(MergePolicy.BOTH).setSelected(true);
        body.add(status);

        String whyNotMerge = choice.whyNotMerge();
        merge.setEnabled(whyNotMerge == null);
        if (whyNotMerge != null) {
            merge.setToolTipText(whyNotMerge);
        }
        replace.setSelected(true);
        replace.addActionListener(e -> refreshPolicies());
        merge.addActionListener(e -> refreshPolicies());
        refreshPolicies();

        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        buttons.add(ok);
        buttons.add(cancel);
        ok.addActionListener(e -> apply());
        cancel.addActionListener(e -> dispose());
        getRootPane().setDefaultButton(ok);

        getContentPane().add(body, BorderLayout.CENTER);
        getContentPane().add(buttons, BorderLayout.SOUTH);
        pack();
        setLocationRelativeTo(owner);
    }

    /**
     * Renames {@code ref} to {@code newName}; when the name is used in its module, asks (modally) whether to
     * replace or merge. Returns the edit's result, or {@code null} when the user cancelled.
     */
    public static EditResult renameOrAsk(Window owner, NetworkEditor editor, NodeRef ref, String newName) {
        String name = newName == null ? "" : newName.strip();
        var module = editor.network().module(ref.module());
        if (module == null || !module.hasNode(name) || name.equals(ref.node())) {
            return editor.renameNode(ref, name);
        }
        MergeReplaceDialog dialog = new MergeReplaceDialog(owner, editor, ref, name);
        dialog.setVisible(true);
        return dialog.result();
    }

    /** The applied edit's result, or null when the dialog was cancelled (or is still open). */
    public EditResult result() {
        return result;
    }

    private void refreshPolicies() {
        for (JRadioButton b : policies.values()) {
            b.setEnabled(merge.isSelected());
        }
    }

    private void apply() {
        MergePolicy policy = MergePolicy.BOTH;
        for (Map.Entry<MergePolicy, JRadioButton> e : policies.entrySet()) {
            if (e.getValue().isSelected()) {
                policy = e.getKey();
            }
        }
        EditResult r = choice.apply(merge.isSelected() ? MergeReplaceChoice.Action.MERGE
                : MergeReplaceChoice.Action.REPLACE, policy);
        if (!r.accepted()) {
            status.setText("Refused: " + r.reason());
            return;
        }
        result = r;
        dispose();
    }

    // for the GUI tests, which click as a user does
    JRadioButton replaceButton() {
        return replace;
    }

    JRadioButton mergeButton() {
        return merge;
    }

    JRadioButton policyButton(MergePolicy policy) {
        return policies.get(policy);
    }

    JButton okButton() {
        return ok;
    }

    JLabel statusLabel() {
        return status;
    }
}
