package org.fdnet.logger.ui;

import static org.fdnet.logger.ui.ConfigPanelScenario.find;
import static org.fdnet.logger.ui.ConfigPanelScenario.onEdt;

import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Window;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import javax.swing.AbstractButton;
import javax.swing.JLabel;
import javax.swing.JTabbedPane;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.fdnet.logger.config.LoggerConfigFile;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.testing.WindowVisibility;

/**
 * Opens the configuration window as {@code fdnet logger --gui --config FILE} does, on a real display, and prints
 * {@code VISIBLE} or {@code PROBLEM ...} lines ({@link WindowVisibility}). With {@code change}, it then types an
 * invalid batch size (printing the reason shown at the field, and taking the screenshot), a valid one, and
 * presses Save; with
 * {@code reopen}, it prints the batch size the field shows. Arguments: CONFIG_FILE change|reopen [SCREENSHOT_PNG]
 */
public final class ConfigPanelVisibilityScenario {
    public static void main(String[] args) throws Exception {
        Path file = Path.of(args[0]);
        LoggerPanel panel = LoggerFrame.openWindow(LoggerConfigFile.load(file), file);
        Window window = SwingUtilities.getWindowAncestor(panel);
        Thread.sleep(500);
        List<String> problems = WindowVisibility.problems(window);
        System.out.println("SIZE " + window.getWidth() + "x" + window.getHeight());
        problems.forEach(p -> System.out.println("PROBLEM " + p));
        if (problems.isEmpty()) {
            System.out.println("VISIBLE");
        }
        JTextField batch = find(panel, LoggerSetting.WRITER_BATCH_SIZE.key(), JTextField.class);
        if (args[1].equals("change")) {
            onEdt(() -> {
                find(panel, "tabs", JTabbedPane.class).setSelectedIndex(1);
                batch.setText("0");
                return null;
            });
            System.out.println("REASON " + onEdt(() -> find(panel, LoggerSetting.WRITER_BATCH_SIZE.key() + ".help",
                    JLabel.class).getText()));
            System.out.println("OUTLINE " + onEdt(() -> batch.getClientProperty("JComponent.outline")));
            onEdt(() -> {
                find(panel, "start", AbstractButton.class).doClick();
                return null;
            });
            System.out.println("START REFUSED " + onEdt(() -> find(panel, "message", JLabel.class).getText()));
            if (args.length > 2) {
                Thread.sleep(300);
                Rectangle r = onEdt(() -> new Rectangle(window.getLocationOnScreen(), window.getSize()));
                ImageIO.write(new Robot().createScreenCapture(r), "png", Path.of(args[2]).toFile());
            }
            onEdt(() -> {
                batch.setText("750");
                return null;
            });
            System.out.println("HELP " + onEdt(() -> find(panel, LoggerSetting.WRITER_BATCH_SIZE.key() + ".help",
                    JLabel.class).getText()));
            System.out.println("SAVED " + onEdt(() -> panel.save(file)));
        } else {
            System.out.println("BATCH " + onEdt(batch::getText));
        }
        onEdt(() -> {
            panel.dispose();
            return null;
        });
        System.exit(0);
    }
}
