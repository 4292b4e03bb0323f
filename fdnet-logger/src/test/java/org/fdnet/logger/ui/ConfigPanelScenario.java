package org.fdnet.logger.ui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.Window;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import javax.imageio.ImageIO;
import javax.swing.AbstractButton;
import javax.swing.JLabel;
import javax.swing.JTable;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.EventClock;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.ValueType;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.testing.OnEdt;

/**
 * Drives the real configuration window on a real display (run in a child JVM by {@code ConfigPanelDisplayTest}):
 * a bad value is refused with its precise message; Start starts the logger; a core connects and its
 * events show in the live status and the clients table; a screenshot of the window is taken; Stop stops.
 * Prints {@code STEP ...} lines and exits 0 only when every step held.
 * Arguments: JDBC_URL USER CONFIG_FILE SCREENSHOT_PNG
 */
public final class ConfigPanelScenario {
    public static void main(String[] args) throws Exception {
        LoggerConfig config = new LoggerConfig().set(LoggerSetting.DATABASE_EMBEDDED, "false")
                .set(LoggerSetting.DATABASE_URL, args[0]).set(LoggerSetting.DATABASE_USER, args[1])
                .set(LoggerSetting.RECEIVER_PORT, "0").set(LoggerSetting.SENDER_PORT, "0")
                .set(LoggerSetting.WRITER_BATCH_TIMEOUT, "200");
        LoggerPanel panel = LoggerFrame.openWindow(config, Path.of(args[2]));
        try {
            run(panel, Path.of(args[3]));
            System.out.println("STEP all passed");
            System.exit(0);
        } catch (Throwable t) {
            // stdout is the test's evidence: the parent test prints it when a step fails
            System.out.println("FAILED: " + t);
            for (Throwable c = t; c != null; c = c.getCause()) {
                for (StackTraceElement e : c.getStackTrace()) {
                    System.out.println("    at " + e);
                }
                if (c.getCause() != null) {
                    System.out.println("caused by: " + c.getCause());
                }
            }
            System.exit(1);
        }
    }

    private static void run(LoggerPanel panel, Path png) throws Exception {
        JTextField batch = find(panel, "writer.batchSize", JTextField.class);
        onEdt(() -> {
            batch.setText("0");
            find(panel, "start", AbstractButton.class).doClick();
            return null;
        });
        String refused = onEdt(() -> find(panel, "message", JLabel.class).getText());
        check(refused.equals("writer.batchSize must be in [1, 1000000], was 0"), "bad value refused: " + refused);
        onEdt(() -> {
            batch.setText("500");
            find(panel, "start", AbstractButton.class).doClick();
            return null;
        });
        waitFor(() -> find(panel, "status", JLabel.class).getText().startsWith("running"), "logger running");
        System.out.println("STEP started: " + onEdt(() -> find(panel, "status", JLabel.class).getText()));
        int port = panel.logger().receiverPort();
        EventClock clock = new EventClock();
        try (LoggerClient core = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", port, "panel-core"))) {
            core.accept(new NodeNamedEvent(0, clock.next(), NodeKind.DATA, new NodeRef("main", "Speed")));
            for (int i = 0; i < 20_000; i++) {
                core.accept(new DataValueEvent(0, clock.next(), ValueType.DOUBLE, Double.toString(i)));
            }
            check(core.flush(30_000), "core's events committed");
            JTable cores = find(panel, "cores", JTable.class);
            waitFor(() -> cores.getRowCount() == 1 && "activated".equals(cores.getValueAt(0, 3))
                    && "panel-core".equals(cores.getValueAt(0, 2)), "core listed as activated");
            waitFor(() -> find(panel, "rates", JLabel.class).getText().contains("committed 20,001"), "status shows commits");
            System.out.println("STEP core shown: " + cores.getValueAt(0, 0) + " " + cores.getValueAt(0, 3));
            System.out.println("STEP status: " + onEdt(() -> find(panel, "cache", JLabel.class).getText()));
            onEdt(() -> {
                find(panel, "tabs", javax.swing.JTabbedPane.class).setSelectedIndex(2); // Server receiver
                return null;
            });
            Thread.sleep(700);
            Window w = SwingUtilities.getWindowAncestor(panel);
            Rectangle r = onEdt(() -> new Rectangle(w.getLocationOnScreen(), w.getSize()));
            BufferedImage shot = new Robot().createScreenCapture(r);
            ImageIO.write(shot, "png", png.toFile());
            System.out.println("STEP screenshot " + png + " " + shot.getWidth() + "x" + shot.getHeight());
        }
        onEdt(() -> {
            find(panel, "stop", AbstractButton.class).doClick();
            return null;
        });
        waitFor(() -> find(panel, "status", JLabel.class).getText().equals("stopped")
                && find(panel, "start", AbstractButton.class).isEnabled(), "logger stopped");
        System.out.println("STEP stopped");
    }

    private static void check(boolean condition, String what) {
        if (!condition) {
            throw new AssertionError(what);
        }
    }

    private static void waitFor(Callable<Boolean> condition, String what) throws Exception {
        long deadline = System.currentTimeMillis() + 30_000;
        while (System.currentTimeMillis() < deadline) {
            if (onEdt(condition)) {
                return;
            }
            Thread.sleep(100);
        }
        throw new AssertionError("timed out waiting for: " + what);
    }

    static <T> T onEdt(Callable<T> c) throws Exception {
        return OnEdt.call(c);
    }

    static <T extends Component> T find(Container root, String name, Class<T> type) {
        for (Component c : root.getComponents()) {
            if (name.equals(c.getName()) && type.isInstance(c)) {
                return type.cast(c);
            }
            if (c instanceof Container child) {
                T found = findOrNull(child, name, type);
                if (found != null) {
                    return found;
                }
            }
        }
        throw new AssertionError("no component " + name);
    }

    private static <T extends Component> T findOrNull(Container root, String name, Class<T> type) {
        try {
            return find(root, name, type);
        } catch (AssertionError e) {
            return null;
        }
    }
}
