package org.fdnet.hi.graph;

import java.awt.Shape;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.awt.geom.RoundRectangle2D;
import org.fdnet.netinfo.NodeKind;

/** The two node shapes (a Data is an oval, a Relation a box) and where a line to the centre meets the border. */
final class NodeShapes {
    static final double DEFAULT_HEIGHT = 40;

    private NodeShapes() {
    }

    static Shape outline(NodeKind kind, Rectangle2D b) {
        return kind == NodeKind.DATA ? new Ellipse2D.Double(b.getX(), b.getY(), b.getWidth(), b.getHeight())
                : new RoundRectangle2D.Double(b.getX(), b.getY(), b.getWidth(), b.getHeight(), 8, 8);
    }

    /** Default width: room for the name. */
    static double defaultWidth(String name, NodeKind kind) {
        double text = 7.0 * name.length() + (kind == NodeKind.DATA ? 44 : 28);
        return Math.max(90, Math.min(260, text));
    }

    /** Where the segment from the box's centre towards {@code toward} leaves the node's shape. */
    static Point2D border(NodeKind kind, Rectangle2D b, Point2D toward) {
        double cx = b.getCenterX();
        double cy = b.getCenterY();
        double dx = toward.getX() - cx;
        double dy = toward.getY() - cy;
        if (dx == 0 && dy == 0) {
            return new Point2D.Double(cx, cy);
        }
        double rx = b.getWidth() / 2;
        double ry = b.getHeight() / 2;
        double t;
        if (kind == NodeKind.DATA) {
            t = 1 / Math.sqrt(dx * dx / (rx * rx) + dy * dy / (ry * ry));
        } else {
            t = Math.min(dx == 0 ? Double.MAX_VALUE : rx / Math.abs(dx), dy == 0 ? Double.MAX_VALUE : ry / Math.abs(dy));
        }
        return new Point2D.Double(cx + dx * t, cy + dy * t);
    }
}
