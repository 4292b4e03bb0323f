package org.fdnet.hi.graph;

import java.awt.Color;
import java.awt.Shape;

/**
 * What {@link GraphPainter} draws on: shapes and centred labels. The screen, a PNG and an SVG file are
 * each one implementation, so all three show the same picture from the same painting code.
 */
public interface Sketch {
    void fill(Shape shape, Color colour);

    void stroke(Shape shape, Color colour, float width, boolean dashed);

    /** A label centred on ({@code cx}, {@code cy}). */
    void text(String text, double cx, double cy, Color colour, boolean bold);
}
