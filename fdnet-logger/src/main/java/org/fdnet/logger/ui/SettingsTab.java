package org.fdnet.logger.ui;

import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.util.EnumMap;
import java.util.Map;
import javax.swing.BorderFactory;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JPasswordField;
import javax.swing.JTextField;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;

/**
 * One tab of the configuration panel: a labelled field for every setting of one of the thesis's panels.
 * Booleans are true/false choices, the password is masked; the description is the tooltip.
 */
final class SettingsTab extends JPanel {
    private final Map<LoggerSetting, JComponent> fields = new EnumMap<>(LoggerSetting.class);

    SettingsTab(LoggerSetting.Panel panel, LoggerConfig config) {
        super(new GridBagLayout());
        setBorder(BorderFactory.createTitledBorder(panel.title() + " properties"));
        GridBagConstraints c = new GridBagConstraints();
        c.insets = new Insets(3, 6, 3, 6);
        c.anchor = GridBagConstraints.WEST;
        int row = 0;
        for (LoggerSetting s : LoggerSetting.values()) {
            if (s.panel() != panel) {
                continue;
            }
            c.gridx = 0;
            c.gridy = row;
            c.weightx = 0;
            c.fill = GridBagConstraints.NONE;
            JLabel label = new JLabel(s.description() + ":");
            label.setToolTipText(s.key());
            add(label, c);
            JComponent field = field(s, config.get(s));
            field.setToolTipText(s.key() + " (default " + s.defaultValue() + ")");
            field.setName(s.key());
            c.gridx = 1;
            c.weightx = 1;
            c.fill = GridBagConstraints.HORIZONTAL;
            add(field, c);
            fields.put(s, field);
            row++;
        }
        c.gridy = row;
        c.weighty = 1;
        add(new JLabel(), c);
    }

    private static JComponent field(LoggerSetting s, String value) {
        if ("true".equals(s.defaultValue()) || "false".equals(s.defaultValue())) {
            JComboBox<String> box = new JComboBox<>(new String[] {"true", "false"});
            box.setSelectedItem(value);
            return box;
        }
        JTextField text = s == LoggerSetting.DATABASE_PASSWORD ? new JPasswordField(value, 24) : new JTextField(value, 24);
        return text;
    }

    /** Copies the fields into the config; the first invalid value throws with its precise message. */
    void applyTo(LoggerConfig config) {
        for (Map.Entry<LoggerSetting, JComponent> e : fields.entrySet()) {
            JComponent f = e.getValue();
            String v = f instanceof JComboBox<?> box ? String.valueOf(box.getSelectedItem()) : ((JTextField) f).getText();
            config.set(e.getKey(), v);
        }
    }

    void setEditable(boolean editable) {
        fields.values().forEach(f -> f.setEnabled(editable));
    }
}
