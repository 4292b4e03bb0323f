package org.fdnet.hi.app;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import javax.swing.RootPaneContainer;

/** A window's content (menu bar, panels, status bar; no title bar) rendered to a PNG, as it is on screen. */
public final class WindowScreenshot {
    private WindowScreenshot() {
    }

    /** Call on the Swing thread, once the window is shown and laid out. */
    public static void write(RootPaneContainer window, Path file) throws IOException {
        var root = window.getRootPane();
        BufferedImage image = new BufferedImage(root.getWidth(), root.getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            root.printAll(g);
        } finally {
            g.dispose();
        }
        if (!ImageIO.write(image, "png", file.toFile())) {
            throw new IOException("no PNG writer in this Java");
        }
    }
}
