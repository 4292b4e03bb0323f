package org.fdnet.logger.ui;

import com.formdev.flatlaf.FlatLightLaf;
import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import javax.imageio.ImageIO;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import org.fdnet.logger.config.LoggerConfig;

/** The window around the {@link LoggerPanel}, and its off-screen rendering for the documentation. */
public final class LoggerFrame {
    /** The window's size when it opens: the panel shows every field at this size. */
    public static final Dimension DEFAULT_SIZE = new Dimension(1024, 700);

    private LoggerFrame() {
    }

    /** Opens the panel in a window (on the event thread); closing the window stops the logger and exits. */
    public static LoggerPanel open(LoggerConfig config, Path file) throws InterruptedException, InvocationTargetException {
        return openWindow(config, file);
    }

    /** The same window; returns the panel (tests drive it). */
    public static LoggerPanel openWindow(LoggerConfig config, Path file) throws InterruptedException, InvocationTargetException {
        AtomicReference<LoggerPanel> panel = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            FlatLightLaf.setup();
            JFrame frame = new JFrame("FDNet network state logger");
            LoggerPanel p = new LoggerPanel(config, file);
            frame.setContentPane(p);
            frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
            frame.addWindowListener(new WindowAdapter() {
                @Override
                public void windowClosed(WindowEvent e) {
                    p.dispose();
                    System.exit(0);
                }
            });
            frame.setSize(DEFAULT_SIZE);
            frame.setMinimumSize(new Dimension(760, 520));
            frame.setLocationByPlatform(true);
            frame.setVisible(true);
            panel.set(p);
        });
        return panel.get();
    }

    /** Renders the panel (first tab) into a PNG without a window; works headless. */
    public static void screenshot(LoggerConfig config, Path file, Path png) throws Exception {
        AtomicReference<BufferedImage> image = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            FlatLightLaf.setup();
            LoggerPanel p = new LoggerPanel(config, file);
            p.setSize(DEFAULT_SIZE);
            layout(p);
            BufferedImage img = new BufferedImage(DEFAULT_SIZE.width, DEFAULT_SIZE.height, BufferedImage.TYPE_INT_RGB);
            Graphics2D g = img.createGraphics();
            p.paint(g);
            g.dispose();
            p.dispose();
            image.set(img);
        });
        if (png.getParent() != null) {
            Files.createDirectories(png.getParent());
        }
        if (!ImageIO.write(image.get(), "png", png.toFile())) {
            throw new IOException("no PNG writer");
        }
    }

    private static void layout(java.awt.Container c) {
        c.doLayout();
        for (java.awt.Component child : c.getComponents()) {
            if (child instanceof java.awt.Container cc) {
                layout(cc);
            }
        }
    }
}
