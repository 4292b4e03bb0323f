package org.fdnet.hi.graph;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Shape;

/** A {@link Sketch} on a Graphics2D: the canvas on screen and PNG export. */
public final class Java2DSketch implements Sketch {
    /** The names' font unless the names need another ({@link org.fdnet.viewer.legible.LegibleFont}). */
    public static final Font PLAIN = new Font(Font.SANS_SERIF, Font.PLAIN, 12);
    private static final float[] DASH = {6f, 4f};

    /** Strokes by width (negative: dashed); a drawing uses a handful. */
    private static final java.util.Map<Float, BasicStroke> STROKES = new java.util.concurrent.ConcurrentHashMap<>();

    private final Graphics2D g;
    private final Font plain;
    private final Font bold;

    public Java2DSketch(Graphics2D g) {
        this(g, true, PLAIN);
    }

    /**
     * {@code smooth} false: no antialiasing, for zoomed-out views of large drawings where it costs most;
     * {@code names}: the font that draws every name of the network.
     */
    public Java2DSketch(Graphics2D g, boolean smooth, Font names) {
        this.g = g;
        this.plain = names;
        this.bold = names.deriveFont(Font.BOLD);
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, smooth ? RenderingHints.VALUE_ANTIALIAS_ON
                : RenderingHints.VALUE_ANTIALIAS_OFF);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
    }

    @Override
    public void fill(Shape shape, Color colour) {
        g.setColor(colour);
        g.fill(shape);
    }

    @Override
    public void stroke(Shape shape, Color colour, float width, boolean dashed) {
        g.setColor(colour);
        g.setStroke(STROKES.computeIfAbsent(dashed ? -width : width, w -> w < 0
                ? new BasicStroke(-w, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f, DASH, 0f)
                : new BasicStroke(w, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND)));
        g.draw(shape);
    }

    @Override
    public void text(String text, double cx, double cy, Color colour, boolean bold) {
        g.setFont(bold ? this.bold : plain);
        g.setColor(colour);
        FontMetrics fm = g.getFontMetrics();
        g.drawString(text, (float) (cx - fm.stringWidth(text) / 2.0),
                (float) (cy + (fm.getAscent() - fm.getDescent()) / 2.0));
    }
}
