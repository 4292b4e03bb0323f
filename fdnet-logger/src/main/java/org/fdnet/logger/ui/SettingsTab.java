package org.fdnet.logger.ui;

import java.awt.BorderLayout;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BiConsumer;
import javax.swing.BorderFactory;
import javax.swing.JLabel;
import javax.swing.JPanel;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;

/**
 * One tab of the configuration panel: a row for every setting of one of the thesis's panels — its short
 * label, its field ({@link SettingField}), its unit and a one-line help — under a line telling which settings
 * a running logger takes at once.
 */
final class SettingsTab extends JPanel {
    private final List<SettingField> fields = new ArrayList<>();

    /** {@code onLiveChange} receives a live setting's new, valid value (applied to a running logger). */
    SettingsTab(LoggerSetting.Panel panel, LoggerConfig config, BiConsumer<LoggerSetting, String> onLiveChange) {
        super(new BorderLayout());
        JPanel grid = new JPanel(new GridBagLayout());
        add(grid, BorderLayout.NORTH);
        setBorder(BorderFactory.createCompoundBorder(BorderFactory.createTitledBorder(panel.title() + " properties"),
                BorderFactory.createEmptyBorder(2, 4, 2, 4)));
        GridBagConstraints c = new GridBagConstraints();
        c.insets = new Insets(3, 4, 3, 4);
        c.anchor = GridBagConstraints.WEST;
        int row = 0;
        for (LoggerSetting s : LoggerSetting.values()) {
            if (s.panel() != panel) {
                continue;
            }
            SettingField field = new SettingField(s, config.get(s), onLiveChange);
            fields.add(field);
            c.gridy = row++;
            c.gridx = 0;
            c.weightx = 0;
            c.fill = GridBagConstraints.NONE;
            grid.add(field.label(), c);
            c.gridx = 1;
            c.fill = GridBagConstraints.HORIZONTAL;
            grid.add(field.input(), c);
            c.gridx = 2;
            c.fill = GridBagConstraints.NONE;
            grid.add(field.unit(), c);
            c.gridx = 3;
            c.weightx = 1;
            c.fill = GridBagConstraints.HORIZONTAL;
            grid.add(field.help(), c);
        }
        if (fields.stream().anyMatch(f -> f.setting().live())) {
            JLabel note = new JLabel(SettingField.LIVE_MARK + " applied at once while the logger runs;"
                    + " the other settings take effect at the next Start");
            note.setForeground(SettingField.QUIET);
            note.setBorder(BorderFactory.createEmptyBorder(8, 4, 3, 4));
            note.setVerticalAlignment(JLabel.TOP);
            add(note, BorderLayout.CENTER);
        }
    }

    List<SettingField> fields() {
        return fields;
    }

    /** Copies the fields into the config; the first invalid value throws with its precise message. */
    void applyTo(LoggerConfig config) {
        fields.forEach(f -> config.set(f.setting(), f.value()));
    }

    /** Shows the config's values in the fields. */
    void show(LoggerConfig config) {
        fields.forEach(f -> f.setValue(config.get(f.setting())));
    }

    /** Running: only the live settings stay editable. */
    void setRunning(boolean running) {
        fields.forEach(f -> f.setRunning(running));
    }
}
