package org.fdnet.roq.view;

import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.fdnet.roq.sim.Heightfield;
import org.fdnet.roq.sim.SensorSnapshot;

/** Renders a {@link RoqPainter} picture into a PNG file (off-screen; works headless). */
public final class RoqScreenshot {
    private RoqScreenshot() {
    }

    /** Paints {@code snapshot} on {@code terrain} into a {@code width} × {@code height} PNG at {@code file}. */
    public static void write(SensorSnapshot snapshot, Heightfield terrain, int width, int height, Path file)
            throws IOException {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            new RoqPainter().paint(g, snapshot, terrain, new Rectangle(0, 0, width, height));
        } finally {
            g.dispose();
        }
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        if (!ImageIO.write(image, "png", file.toFile())) {
            throw new IOException("no PNG writer in this JVM for " + file);
        }
    }
}
