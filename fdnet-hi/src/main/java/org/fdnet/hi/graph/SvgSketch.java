package org.fdnet.hi.graph;

import java.awt.Color;
import java.awt.Shape;
import java.awt.geom.PathIterator;
import java.util.Locale;

/** A {@link Sketch} that writes SVG 1.1 elements: every shape as a path, every label as a centred text. */
public final class SvgSketch implements Sketch {
    private final StringBuilder body = new StringBuilder();
    private final double dx;
    private final double dy;

    /** Everything drawn is shifted by ({@code dx}, {@code dy}) in the document. */
    public SvgSketch(double dx, double dy) {
        this.dx = dx;
        this.dy = dy;
    }

    @Override
    public void fill(Shape shape, Color colour) {
        body.append("<path d=\"").append(path(shape)).append("\" fill=\"").append(hex(colour)).append('"')
                .append(opacity("fill-opacity", colour)).append("/>\n");
    }

    @Override
    public void stroke(Shape shape, Color colour, float width, boolean dashed) {
        body.append("<path d=\"").append(path(shape)).append("\" fill=\"none\" stroke=\"").append(hex(colour))
                .append("\" stroke-width=\"").append(num(width)).append('"')
                .append(opacity("stroke-opacity", colour))
                .append(dashed ? " stroke-dasharray=\"6 4\"" : "").append(" stroke-linejoin=\"round\"/>\n");
    }

    @Override
    public void text(String text, double cx, double cy, Color colour, boolean bold) {
        body.append("<text x=\"").append(num(cx)).append("\" y=\"").append(num(cy))
                .append("\" text-anchor=\"middle\" dominant-baseline=\"central\" font-family=\"sans-serif\" font-size=\"12\"")
                .append(bold ? " font-weight=\"bold\"" : "").append(" fill=\"").append(hex(colour)).append('"')
                .append(opacity("fill-opacity", colour)).append('>').append(escape(text)).append("</text>\n");
    }

    /** The whole document, {@code width} × {@code height}, with a white background. */
    public String document(double width, double height) {
        return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                + "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + num(width) + "\" height=\""
                + num(height) + "\" viewBox=\"0 0 " + num(width) + " " + num(height) + "\">\n"
                + "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
                + "<g transform=\"translate(" + num(dx) + " " + num(dy) + ")\">\n" + body + "</g>\n</svg>\n";
    }

    private static String path(Shape shape) {
        StringBuilder d = new StringBuilder();
        double[] c = new double[6];
        for (PathIterator it = shape.getPathIterator(null); !it.isDone(); it.next()) {
            switch (it.currentSegment(c)) {
                case PathIterator.SEG_MOVETO -> d.append('M').append(num(c[0])).append(' ').append(num(c[1]));
                case PathIterator.SEG_LINETO -> d.append('L').append(num(c[0])).append(' ').append(num(c[1]));
                case PathIterator.SEG_QUADTO -> d.append('Q').append(num(c[0])).append(' ').append(num(c[1]))
                        .append(' ').append(num(c[2])).append(' ').append(num(c[3]));
                case PathIterator.SEG_CUBICTO -> d.append('C').append(num(c[0])).append(' ').append(num(c[1]))
                        .append(' ').append(num(c[2])).append(' ').append(num(c[3]))
                        .append(' ').append(num(c[4])).append(' ').append(num(c[5]));
                case PathIterator.SEG_CLOSE -> d.append('Z');
                default -> throw new IllegalStateException("unknown path segment");
            }
        }
        return d.toString();
    }

    private static String hex(Color c) {
        return String.format(Locale.ROOT, "#%02x%02x%02x", c.getRed(), c.getGreen(), c.getBlue());
    }

    private static String opacity(String attribute, Color c) {
        return c.getAlpha() == 255 ? "" : " " + attribute + "=\"" + num(c.getAlpha() / 255.0) + "\"";
    }

    private static String num(double v) {
        return String.format(Locale.ROOT, "%.2f", v).replaceAll("\\.?0+$", "");
    }

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
