package org.fdnet.hi.graph;

import java.awt.Color;
import java.awt.Shape;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.util.Set;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * Paints a {@link GraphScene} on a {@link Sketch}, in model coordinates: connections first (Readers grey,
 * Writers dark, not-made ones dashed, names at the middle), then nodes (Datas as ovals, Relations as boxes)
 * with their names and, in live mode, a Data's latest value in green under it. The selection is outlined blue; when relatives are highlighted, the others fade.
 */
public final class GraphPainter {
    private static final Color READER = new Color(0x8A9099);
    private static final Color WRITER = new Color(0x3B4250);
    private static final Color SELECTED = new Color(0x1F6FEB);
    private static final Color HIGHLIGHT = new Color(0xF0A020);
    private static final Color TEXT = new Color(0x1E2430);
    private static final Color LIVE_VALUE = new Color(0x0B7A3E);

    /** Names are 12 model units high: below this scale they would be under 5 pixels. */
    static final double LABEL_SCALE = 0.42;

    private final GraphScene scene;
    private boolean labels = true;

    public GraphPainter(GraphScene scene) {
        this.scene = scene;
    }

    /** Paints everything at full detail (exports). */
    public void paint(Sketch sketch, Rectangle2D clip) {
        paint(sketch, clip, 1);
    }

    /**
     * Paints what lies in {@code clip} (model coordinates; {@code null}: everything) at {@code scale} screen
     * pixels per model unit. Below {@link #LABEL_SCALE} names would be unreadably small and are left out,
     * which keeps a zoomed-out 1,000-node drawing fluid.
     */
    public void paint(Sketch sketch, Rectangle2D clip, double scale) {
        paint(sketch, clip, scale, Layer.ALL);
    }

    /** As above, only what belongs to {@code layer}. */
    public void paint(Sketch sketch, Rectangle2D clip, double scale, Layer layer) {
        labels = scale >= LABEL_SCALE;
        Set<NodeRef> lit = scene.highlighted();
        Set<NodeRef> moving = scene.selection();
        boolean fading = !lit.isEmpty();
        for (ConnectionRef c : scene.visibleConnections()) {
            if (!layer.has(moving.contains(c.connection().data()) || moving.contains(c.connection().relation()))) {
                continue;
            }
            Line2D s = scene.segment(c.connection());
            if (s == null || clip != null && !s.getBounds2D().intersects(clip) && !clip.intersectsLine(s)) {
                continue;
            }
            boolean faded = fading && !(lit.contains(c.connection().data()) && lit.contains(c.connection().relation()));
            paintConnection(sketch, s, c, faded);
        }
        for (NodeRef ref : scene.visibleNodes()) {
            if (!layer.has(moving.contains(ref))) {
                continue;
            }
            Rectangle2D b = scene.bounds(ref);
            if (b == null || clip != null && !b.intersects(clip)) {
                continue;
            }
            paintNode(sketch, ref, b, fading && !lit.contains(ref));
        }
    }

    /** What a paint covers: everything, or, while the selection is dragged, what stays or what moves with it. */
    public enum Layer {
        ALL, STILL, MOVING;

        /** Whether a node, or a connection, that moves with the selection or not belongs to this layer. */
        boolean has(boolean movesWithSelection) {
            return this == ALL || movesWithSelection == (this == MOVING);
        }
    }

    private void paintConnection(Sketch sketch, Line2D s, ConnectionRef c, boolean faded) {
        ConnectionInfo info = c.connection();
        boolean selected = c.equals(scene.selectedConnection());
        Color colour = selected ? SELECTED : info.kind() == ConnectionKind.READER ? READER : WRITER;
        colour = faded ? fade(colour) : colour;
        float width = selected ? 3f : 1.6f;
        sketch.stroke(s, colour, width, !info.exists());
        sketch.fill(arrowHead(s, selected ? 14 : 11), colour);
        if (labels && info.name() != null) {
            sketch.text(info.name(), (s.getX1() + s.getX2()) / 2, (s.getY1() + s.getY2()) / 2 - 9, colour, false);
        }
    }

    private void paintNode(Sketch sketch, NodeRef ref, Rectangle2D b, boolean faded) {
        NodeInfo node = scene.network().node(ref);
        Shape outline = NodeShapes.outline(node.kind(), b);
        Color module = scene.moduleColour(ref.module());
        sketch.fill(outline, faded ? fade(scene.fillColour(ref)) : scene.fillColour(ref));
        if (scene.selection().contains(ref)) {
            sketch.stroke(outline, SELECTED, 3.5f, false);
        } else if (!faded && !scene.highlighted().isEmpty()) {
            sketch.stroke(outline, HIGHLIGHT, ref.equals(scene.highlightRoot()) ? 4f : 2.5f, false);
        } else {
            sketch.stroke(outline, faded ? fade(module) : module, 2f, false);
        }
        if (!labels) {
            return;
        }
        Color text = luminance(scene.fillColour(ref)) < 0.5 ? Color.WHITE : TEXT;
        sketch.text(ref.node(), b.getCenterX(), b.getCenterY(), faded ? fade(text) : text,
                node.kind() == org.fdnet.netinfo.NodeKind.RELATION);
        String live = scene.liveValue(ref);
        if (live != null) {
            sketch.text(live, b.getCenterX(), b.getMaxY() + 9, faded ? fade(LIVE_VALUE) : LIVE_VALUE, false);
        }
    }

    private static Shape arrowHead(Line2D s, double length) {
        double dx = s.getX2() - s.getX1();
        double dy = s.getY2() - s.getY1();
        double d = Math.hypot(dx, dy);
        if (d == 0) {
            return new Path2D.Double();
        }
        double ux = dx / d;
        double uy = dy / d;
        double half = length * 0.45;
        Path2D.Double head = new Path2D.Double();
        head.moveTo(s.getX2(), s.getY2());
        head.lineTo(s.getX2() - ux * length - uy * half, s.getY2() - uy * length + ux * half);
        head.lineTo(s.getX2() - ux * length + uy * half, s.getY2() - uy * length - ux * half);
        head.closePath();
        return head;
    }

    private static double luminance(Color c) {
        return (0.299 * c.getRed() + 0.587 * c.getGreen() + 0.114 * c.getBlue()) / 255;
    }

    /** Most of the way to white, opaque, so lines behind a faded node stay hidden. */
    private static Color fade(Color c) {
        return new Color(towardWhite(c.getRed()), towardWhite(c.getGreen()), towardWhite(c.getBlue()));
    }

    private static int towardWhite(int v) {
        return (int) Math.round(v * 0.22 + 255 * 0.78);
    }
}
