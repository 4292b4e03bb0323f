package org.fdnet.hi.graph;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.AffineTransform;
import java.awt.image.BufferedImage;
import java.util.function.Consumer;

/**
 * The drawing without what a drag moves, kept while the selection is dragged: each frame copies it and paints only
 * the selected nodes and their connections over it, so a drag costs the same however many nodes and lines the
 * view holds. It is painted afresh when anything else changes (the scene's {@link GraphScene#stillRevision()}),
 * the view is panned or zoomed, or the canvas is resized.
 */
final class DragBackdrop {
    private BufferedImage image;
    private long stillRevision = -1;
    private AffineTransform view;
    private int width;
    private int height;
    private double deviceScaleX;
    private double deviceScaleY;

    /**
     * Copies the backdrop onto {@code g} (component coordinates), painting it first if it is not the drawing of
     * this scene state, view and size.
     *
     * @param still paints what stays, in component coordinates, on the graphics it is given
     */
    void copyTo(Graphics2D g, long sceneStill, AffineTransform viewNow, int w, int h, Color background,
                Consumer<Graphics2D> still) {
        AffineTransform device = g.getTransform();
        double sx = device.getScaleX();
        double sy = device.getScaleY();
        if (image == null || sceneStill != stillRevision || !viewNow.equals(view) || w != width || h != height
                || sx != deviceScaleX || sy != deviceScaleY) {
            image = new BufferedImage(Math.max(1, (int) Math.ceil(w * sx)), Math.max(1, (int) Math.ceil(h * sy)),
                    BufferedImage.TYPE_INT_RGB);
            Graphics2D ig = image.createGraphics();
            try {
                ig.scale(sx, sy);
                ig.setColor(background);
                ig.fillRect(0, 0, w, h);
                still.accept(ig);
            } finally {
                ig.dispose();
            }
            stillRevision = sceneStill;
            view = new AffineTransform(viewNow);
            width = w;
            height = h;
            deviceScaleX = sx;
            deviceScaleY = sy;
        }
        g.drawImage(image, 0, 0, w, h, null);
    }

    /** Lets the image go (the drag is over). */
    void clear() {
        image = null;
        view = null;
        stillRevision = -1;
    }

    /** Whether a backdrop is held (for tests). */
    boolean held() {
        return image != null;
    }
}
