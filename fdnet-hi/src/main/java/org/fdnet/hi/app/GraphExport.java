package org.fdnet.hi.app;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.fdnet.hi.graph.GraphPainter;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.hi.graph.Java2DSketch;
import org.fdnet.hi.graph.SvgSketch;

/** The whole drawing (every visible node, at scale 1, with a margin) as PNG or SVG, painted by the same painter as the screen. */
public final class GraphExport {
    private static final double MARGIN = 20;

    private GraphExport() {
    }

    public static void png(GraphScene scene, Path file) throws IOException {
        Rectangle2D e = scene.extent();
        int w = (int) Math.ceil(e.getWidth() + 2 * MARGIN);
        int h = (int) Math.ceil(e.getHeight() + 2 * MARGIN);
        BufferedImage image = new BufferedImage(Math.max(w, 1), Math.max(h, 1), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, image.getWidth(), image.getHeight());
            g.translate(MARGIN - e.getX(), MARGIN - e.getY());
            new GraphPainter(scene).paint(new Java2DSketch(g), null);
        } finally {
            g.dispose();
        }
        if (!ImageIO.write(image, "png", file.toFile())) {
            throw new IOException("no PNG writer in this Java");
        }
    }

    public static void svg(GraphScene scene, Path file) throws IOException {
        Rectangle2D e = scene.extent();
        SvgSketch sketch = new SvgSketch(MARGIN - e.getX(), MARGIN - e.getY());
        new GraphPainter(scene).paint(sketch, null);
        Files.writeString(file, sketch.document(e.getWidth() + 2 * MARGIN, e.getHeight() + 2 * MARGIN),
                StandardCharsets.UTF_8);
    }
}
