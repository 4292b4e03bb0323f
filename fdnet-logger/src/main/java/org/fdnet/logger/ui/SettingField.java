package org.fdnet.logger.ui;

import java.awt.Color;
import java.awt.event.FocusAdapter;
import java.awt.event.FocusEvent;
import java.util.function.BiConsumer;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPasswordField;
import javax.swing.JTextField;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;

/**
 * What the panel shows of one {@link LoggerSetting}: its short label, its input (a check box for a switch, a
 * masked field for the password, a text field otherwise), its unit and its help line. The value is checked
 * against the setting's rule ({@link LoggerConfig#check}) as it is typed; an invalid one turns the field red
 * and the help line into the reason. The whole explanation, the key and the default are the tooltip.
 *
 * <p>Component names (for tests): the input is named by the setting's key, the help line {@code KEY.help}.
 */
final class SettingField {
    static final String LIVE_MARK = "●";
    static final Color QUIET = new Color(0x60, 0x66, 0x70);
    private static final Color LIVE = new Color(0x1b, 0x7f, 0x3a);
    private static final Color ERROR = new Color(0xc0, 0x1c, 0x1c);
    private static final int COLUMNS = 14;

    private final LoggerSetting setting;
    private final JLabel label;
    private final JComponent input;
    private final JLabel unit;
    private final JLabel help;
    private final BiConsumer<LoggerSetting, String> onLiveChange;
    private boolean running;
    private String applied;

    SettingField(LoggerSetting setting, String value, BiConsumer<LoggerSetting, String> onLiveChange) {
        this.setting = setting;
        this.onLiveChange = onLiveChange;
        this.applied = value;
        label = new JLabel(setting.label() + (setting.live() ? " " + LIVE_MARK : ""));
        unit = new JLabel(setting.unit());
        unit.setForeground(QUIET);
        help = new JLabel(setting.help());
        help.setName(setting.key() + ".help");
        help.setForeground(QUIET);
        input = setting.isSwitch() ? new JCheckBox() : setting == LoggerSetting.DATABASE_PASSWORD
                ? new JPasswordField(COLUMNS) : new JTextField(COLUMNS);
        input.setName(setting.key());
        String tip = "<html><b>" + setting.key() + "</b> (default " + (setting.defaultValue().isEmpty() ? "empty"
                : setting.defaultValue()) + (setting.live() ? "; applied at once while running" : "; takes effect at the next Start")
                + ")<br>" + setting.description() + "</html>";
        label.setToolTipText(tip);
        input.setToolTipText(tip);
        help.setToolTipText(tip);
        setValue(value);
        if (input instanceof JTextField text) {
            text.getDocument().addDocumentListener(new DocumentListener() {
                @Override
                public void insertUpdate(DocumentEvent e) {
                    check();
                }

                @Override
                public void removeUpdate(DocumentEvent e) {
                    check();
                }

                @Override
                public void changedUpdate(DocumentEvent e) {
                    check();
                }
            });
            text.addActionListener(e -> applyLive());
            text.addFocusListener(new FocusAdapter() {
                @Override
                public void focusLost(FocusEvent e) {
                    applyLive();
                }
            });
        } else {
            ((JCheckBox) input).addActionListener(e -> applyLive());
        }
    }

    LoggerSetting setting() {
        return setting;
    }

    JLabel label() {
        return label;
    }

    JComponent input() {
        return input;
    }

    JLabel unit() {
        return unit;
    }

    JLabel help() {
        return help;
    }

    String value() {
        return input instanceof JCheckBox box ? Boolean.toString(box.isSelected()) : ((JTextField) input).getText();
    }

    void setValue(String value) {
        if (input instanceof JCheckBox box) {
            box.setSelected(Boolean.parseBoolean(value));
        } else {
            ((JTextField) input).setText(value);
        }
        check();
    }

    /** The reason the typed value is refused, or null when it is valid; shown at the field. */
    String check() {
        String reason = null;
        try {
            LoggerConfig.check(setting, value());
        } catch (IllegalArgumentException e) {
            reason = e.getMessage();
        }
        input.putClientProperty("JComponent.outline", reason == null ? null : "error");
        help.setText(reason == null ? setting.help() : reason);
        help.setForeground(reason == null ? QUIET : ERROR);
        input.repaint();
        return reason;
    }

    /** Running, the settings a running logger cannot take are greyed; the live ones stay editable. */
    void setRunning(boolean running) {
        this.running = running;
        applied = value();
        input.setEnabled(!running || setting.live());
        label.setForeground(running && setting.live() ? LIVE : null);
    }

    private void applyLive() {
        String v = value();
        if (!running || !setting.live() || v.equals(applied) || check() != null) {
            return;
        }
        applied = v;
        onLiveChange.accept(setting, v);
    }
}
