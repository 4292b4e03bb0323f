package org.fdnet.hi.text;

import java.awt.Graphics2D;
import java.awt.Window;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;

import javax.imageio.ImageIO;
import javax.swing.RootPaneContainer;

/** Paints a window's content off-screen into a PNG (no window manager decorations), for the user guide. */
public final class FrameScreenshot {
    private FrameScreenshot() {
    }

    /** Call on the event thread. */
    public static void write(Window window, Path png) throws IOException {
        var root = ((RootPaneContainer) window).getRootPane();
        root.validate();
        BufferedImage image = new BufferedImage(root.getWidth(), root.getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            root.paint(g);
        } finally {
            g.dispose();
        }
        ImageIO.write(image, "png", png.toFile());
    }
}
