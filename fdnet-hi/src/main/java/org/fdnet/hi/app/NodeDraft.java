package org.fdnet.hi.app;

import java.awt.GridLayout;
import java.util.List;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JTextField;
import org.fdnet.netinfo.NodeKind;

/** The few things a new node needs from the graphic panel: module, name and class (the rest is edited afterwards). */
record NodeDraft(String module, String name, String className) {
    static NodeDraft ask(HiWindow owner, NodeKind kind, List<String> modules, String module) {
        JComboBox<String> moduleBox = new JComboBox<>(modules.toArray(String[]::new));
        moduleBox.setSelectedItem(module);
        JTextField name = new JTextField(20);
        JTextField className = new JTextField(kind == NodeKind.DATA ? "org.fdnet.runtime.library.DoubleData"
                : "org.fdnet.runtime.library.Expression", 28);
        JPanel form = new JPanel(new GridLayout(0, 2, 6, 4));
        form.add(new JLabel("Module"));
        form.add(moduleBox);
        form.add(new JLabel("Name"));
        form.add(name);
        form.add(new JLabel("Class"));
        form.add(className);
        int answer = JOptionPane.showConfirmDialog(owner, form, "New " + kind.label(), JOptionPane.OK_CANCEL_OPTION,
                JOptionPane.PLAIN_MESSAGE);
        if (answer != JOptionPane.OK_OPTION) {
            return null;
        }
        return new NodeDraft((String) moduleBox.getSelectedItem(), name.getText().trim(), className.getText().trim());
    }
}
