package org.fdnet.roq.view;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Locale;
import org.fdnet.roq.sim.FragileCell;
import org.fdnet.roq.sim.Heightfield;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.SensorSnapshot;

/**
 * Draws the RoQ and its course from a {@link SensorSnapshot}: a top view of the whole course (terrain heights
 * shaded, fragile cells, broken ones open), a side view of the ground under the robot with the robot in profile,
 * and a panel of the sensed values (inclinometer, soles, ranges, the depth image). Robot pose comes from the
 * snapshot's ground truth — this is the observer's view, not the robot's. The top view also shows the support
 * polygon of the feet in contact, the centre of mass and, when given, the path so far. Reusable: {@link #paint} into any
 * {@link Graphics2D} and bounds. Not thread-safe (one painter per component).
 */
public final class RoqPainter {
    private static final Color BACKGROUND = new Color(0xF4F4F0);
    private static final Color BODY = new Color(0x3B5B92);
    private static final Color LEG = new Color(0x20262E);
    private static final Color CONTACT = new Color(0x2E9E44);
    private static final Color AIR = new Color(0xC8C8C8);
    private static final Color CELL = new Color(0xE39B2D);
    private static final Color BROKEN = new Color(0x5A2A0A);
    private static final Color COM = new Color(0xC0392B);
    private static final Color GROUND = new Color(0x8B7D6B);
    /** The support polygon: outline and translucent fill. */
    static final Color SUPPORT = new Color(0x7D3C98);
    private static final Color SUPPORT_FILL = new Color(0x7D, 0x3C, 0x98, 60);
    /** The path the body has taken. */
    static final Color PATH = new Color(0x1ABC9C);
    /** Length of ground the side view shows around the robot, m. */
    private static final double SIDE_SPAN = 2.0;
    private static final Font FONT = new Font(Font.MONOSPACED, Font.PLAIN, 12);

    private Heightfield shadedFor;
    private BufferedImage shading;
    private final double[] leg = new double[12];
    private final double[] world = new double[12];
    private final double[] point = new double[3];
    private final double[] pointInWorld = new double[3];
    private final double[] support = new double[2 * RoqGeometry.LEGS];
    private double[] path = new double[0];
    private int pathPoints;

    /**
     * Paints the course and robot into {@code bounds}: top view above, side view and the sensor panel below.
     */
    public void paint(Graphics2D g, SensorSnapshot s, Heightfield terrain, Rectangle bounds) {
        paint(g, s, terrain, bounds, new double[0], 0);
    }

    /**
     * As {@link #paint(Graphics2D, SensorSnapshot, Heightfield, Rectangle)}, with the path so far in the top view:
     * {@code points} body positions, x and y in turn in {@code path} (world metres).
     */
    public void paint(Graphics2D g, SensorSnapshot s, Heightfield terrain, Rectangle bounds, double[] path, int points) {
        this.path = path;
        this.pathPoints = points;
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            g2.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g2.setColor(BACKGROUND);
            g2.fill(bounds);
            int panelWidth = Math.min(260, bounds.width / 3);
            int viewWidth = bounds.width - panelWidth;
            int topHeight = (int) Math.min(bounds.height * 0.62, viewWidth * terrain.width() / terrain.length() + 30);
            Rectangle top = new Rectangle(bounds.x, bounds.y, viewWidth, topHeight);
            Rectangle side = new Rectangle(bounds.x, bounds.y + topHeight, viewWidth, bounds.height - topHeight);
            Rectangle panel = new Rectangle(bounds.x + viewWidth, bounds.y, panelWidth, bounds.height);
            paintTop(g2, s, terrain, top);
            paintSide(g2, s, terrain, side);
            paintPanel(g2, s, panel);
        } finally {
            g2.dispose();
        }
    }

    /** Body-frame point (bx, by, bz) to world, component {@code i}. */
    private double toWorld(SensorSnapshot s, double bx, double by, double bz, int i) {
        point[0] = bx;
        point[1] = by;
        point[2] = bz;
        s.groundTruthToWorld(point, pointInWorld);
        return pointInWorld[i];
    }

    private void legInWorld(SensorSnapshot s, int l) {
        RoqGeometry.legInBody(l, s.jointAngle(3 * l), s.jointAngle(3 * l + 1), s.jointAngle(3 * l + 2), leg);
        for (int k = 0; k < 4; k++) {
            for (int i = 0; i < 3; i++) {
                world[3 * k + i] = toWorld(s, leg[3 * k], leg[3 * k + 1], leg[3 * k + 2], i);
            }
        }
    }

    // ---- top view --------------------------------------------------------------------------------------------

    private void paintTop(Graphics2D g, SensorSnapshot s, Heightfield t, Rectangle r) {
        double scale = Math.min((r.width - 20) / t.length(), (r.height - 30) / t.width());
        double ox = r.x + r.width / 2.0;
        double oy = r.y + 20 + (r.height - 30) / 2.0;
        g.setFont(FONT);
        g.setColor(LEG);
        g.drawString(String.format(Locale.ROOT, "top view  %.1f x %.1f m  (shade: height 0..%.2f m)", t.length(), t.width(),
                t.maxHeight()), r.x + 10, r.y + 14);
        BufferedImage img = shading(t);
        g.drawImage(img, (int) Math.round(ox - t.length() / 2 * scale), (int) Math.round(oy - t.width() / 2 * scale),
                (int) Math.round(t.length() * scale), (int) Math.round(t.width() * scale), null);
        List<FragileCell> cells = t.fragileCells();
        for (int i = 0; i < cells.size(); i++) {
            FragileCell c = cells.get(i);
            Rectangle2D.Double box = new Rectangle2D.Double(ox + (c.x() - c.sizeX() / 2) * scale,
                    oy - (c.y() + c.sizeY() / 2) * scale, c.sizeX() * scale, c.sizeY() * scale);
            boolean broken = s.isCellBroken(i);
            g.setColor(broken ? BROKEN : CELL);
            g.fill(box);
            g.setColor(LEG);
            g.draw(box);
            if (broken) {
                g.setColor(CELL);
                g.draw(new Line2D.Double(box.x, box.y, box.x + box.width, box.y + box.height));
                g.draw(new Line2D.Double(box.x + box.width, box.y, box.x, box.y + box.height));
            }
        }
        // body outline
        double hl = RoqGeometry.BODY_LENGTH / 2;
        double hw = RoqGeometry.BODY_WIDTH / 2;
        Path2D.Double body = new Path2D.Double();
        double[][] corners = {{hl, hw}, {-hl, hw}, {-hl, -hw}, {hl, -hw}};
        for (int k = 0; k < 4; k++) {
            double wx = toWorld(s, corners[k][0], corners[k][1], 0, 0);
            double wy = toWorld(s, corners[k][0], corners[k][1], 0, 1);
            if (k == 0) {
                body.moveTo(ox + wx * scale, oy - wy * scale);
            } else {
                body.lineTo(ox + wx * scale, oy - wy * scale);
            }
        }
        body.closePath();
        g.setColor(new Color(BODY.getRed(), BODY.getGreen(), BODY.getBlue(), 200));
        g.fill(body);
        g.setColor(LEG);
        g.draw(body);
        double nx = toWorld(s, hl, 0, 0, 0);
        double ny = toWorld(s, hl, 0, 0, 1);
        double cx = s.groundTruthBodyPosition(0);
        double cy = s.groundTruthBodyPosition(1);
        g.setColor(Color.WHITE);
        g.setStroke(new BasicStroke(2f));
        g.draw(new Line2D.Double(ox + cx * scale, oy - cy * scale, ox + nx * scale, oy - ny * scale));
        drawPath(g, ox, oy, scale);
        int feet = 0;
        for (int l = 0; l < RoqGeometry.LEGS; l++) {
            legInWorld(s, l);
            if (s.footContact(l)) {
                support[2 * feet] = world[9];
                support[2 * feet + 1] = world[10];
                feet++;
            }
        }
        drawSupportPolygon(g, feet, ox, oy, scale);
        for (int l = 0; l < RoqGeometry.LEGS; l++) {
            legInWorld(s, l);
            drawLeg(g, s, l, ox, oy, scale, 0, 1);
        }
        mark(g, ox + s.groundTruthCentreOfMass(0) * scale, oy - s.groundTruthCentreOfMass(1) * scale);
    }

    private void drawPath(Graphics2D g, double ox, double oy, double scale) {
        if (pathPoints < 2) {
            return;
        }
        Path2D.Double p = new Path2D.Double();
        p.moveTo(ox + path[0] * scale, oy - path[1] * scale);
        for (int k = 1; k < pathPoints; k++) {
            p.lineTo(ox + path[2 * k] * scale, oy - path[2 * k + 1] * scale);
        }
        g.setColor(PATH);
        g.setStroke(new BasicStroke(2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        g.draw(p);
    }

    /** The polygon of the feet in contact (2 feet: a line), corners in order of angle around their centre. */
    private void drawSupportPolygon(Graphics2D g, int feet, double ox, double oy, double scale) {
        if (feet < 2) {
            return;
        }
        double mx = 0;
        double my = 0;
        for (int k = 0; k < feet; k++) {
            mx += support[2 * k] / feet;
            my += support[2 * k + 1] / feet;
        }
        Integer[] order = new Integer[feet];
        for (int k = 0; k < feet; k++) {
            order[k] = k;
        }
        double cx = mx;
        double cy = my;
        java.util.Arrays.sort(order, java.util.Comparator.comparingDouble(
                k -> Math.atan2(support[2 * k + 1] - cy, support[2 * k] - cx)));
        Path2D.Double p = new Path2D.Double();
        for (int k = 0; k < feet; k++) {
            double x = ox + support[2 * order[k]] * scale;
            double y = oy - support[2 * order[k] + 1] * scale;
            if (k == 0) {
                p.moveTo(x, y);
            } else {
                p.lineTo(x, y);
            }
        }
        p.closePath();
        g.setColor(SUPPORT_FILL);
        g.fill(p);
        g.setColor(SUPPORT);
        g.setStroke(new BasicStroke(1.5f));
        g.draw(p);
    }

    private void drawLeg(Graphics2D g, SensorSnapshot s, int l, double ox, double oy, double scale, int h, int v) {
        g.setColor(LEG);
        g.setStroke(new BasicStroke(3f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        Path2D.Double p = new Path2D.Double();
        p.moveTo(ox + world[h] * scale, oy - world[v] * scale);
        for (int k = 1; k < 4; k++) {
            p.lineTo(ox + world[3 * k + h] * scale, oy - world[3 * k + v] * scale);
        }
        g.draw(p);
        double rad = Math.max(3, RoqGeometry.FOOT_RADIUS * scale);
        Ellipse2D.Double foot = new Ellipse2D.Double(ox + world[9 + h] * scale - rad, oy - world[9 + v] * scale - rad,
                2 * rad, 2 * rad);
        g.setColor(s.footContact(l) ? CONTACT : AIR);
        g.fill(foot);
        g.setColor(LEG);
        g.setStroke(new BasicStroke(1f));
        g.draw(foot);
    }

    private static void mark(Graphics2D g, double x, double y) {
        g.setColor(COM);
        g.setStroke(new BasicStroke(2f));
        g.draw(new Line2D.Double(x - 6, y, x + 6, y));
        g.draw(new Line2D.Double(x, y - 6, x, y + 6));
        g.draw(new Ellipse2D.Double(x - 4, y - 4, 8, 8));
    }

    private BufferedImage shading(Heightfield t) {
        if (t != shadedFor) {
            BufferedImage img = new BufferedImage(t.cols(), t.rows(), BufferedImage.TYPE_INT_RGB);
            double min = t.minHeight();
            double range = Math.max(0.01, t.maxHeight() - min);
            for (int r = 0; r < t.rows(); r++) {
                for (int c = 0; c < t.cols(); c++) {
                    double f = (t.height(r, c) - min) / range;
                    int v = (int) (225 - 120 * f);
                    img.setRGB(c, t.rows() - 1 - r, new Color(v, (int) (v * 0.96), (int) (v * 0.88)).getRGB());
                }
            }
            shading = img;
            shadedFor = t;
        }
        return shading;
    }

    // ---- side view -------------------------------------------------------------------------------------------

    private void paintSide(Graphics2D g, SensorSnapshot s, Heightfield t, Rectangle r) {
        // A window of SIDE_SPAN metres around the robot (clamped to the course), true proportions.
        double by = s.groundTruthBodyPosition(1);
        double span = Math.min(SIDE_SPAN, t.length());
        double x0 = Math.max(-t.length() / 2, Math.min(t.length() / 2 - span, s.groundTruthBodyPosition(0) - span / 2));
        double zTop = Math.max(t.maxHeight(), s.groundTruthBodyPosition(2)) + 0.25;
        double zBottom = Math.min(t.minHeight(), 0) - 0.05;
        double scale = Math.min((r.width - 20) / span, (r.height - 30) / (zTop - zBottom));
        double ox = r.x + 10 - x0 * scale;
        double oy = r.y + 20 + zTop * scale;
        g.setFont(FONT);
        g.setColor(LEG);
        g.drawString(String.format(Locale.ROOT, "side view  x %.1f .. %.1f m, ground along y = %.2f m", x0, x0 + span, by),
                r.x + 10, r.y + 14);
        java.awt.Shape clip = g.getClip();
        g.clip(new Rectangle(r.x, r.y + 18, r.width, r.height - 18));
        Path2D.Double ground = new Path2D.Double();
        int n = 400;
        ground.moveTo(ox + x0 * scale, oy - zBottom * scale);
        for (int i = 0; i <= n; i++) {
            double x = x0 + i * span / n;
            ground.lineTo(ox + x * scale, oy - t.heightAt(x, by) * scale);
        }
        ground.lineTo(ox + (x0 + span) * scale, oy - zBottom * scale);
        ground.closePath();
        g.setColor(GROUND);
        g.fill(ground);
        List<FragileCell> cells = t.fragileCells();
        for (int i = 0; i < cells.size(); i++) {
            FragileCell c = cells.get(i);
            if (Math.abs(c.y() - by) > c.sizeY() / 2 + 0.5) {
                continue;
            }
            double top = s.isCellBroken(i) ? t.cellTop(i) - c.height() - 0.02 : t.cellTop(i);
            g.setColor(s.isCellBroken(i) ? BROKEN : CELL);
            g.fill(new Rectangle2D.Double(ox + (c.x() - c.sizeX() / 2) * scale, oy - top * scale, c.sizeX() * scale,
                    c.height() * scale));
        }
        // body in profile: its x–z outline
        double hl = RoqGeometry.BODY_LENGTH / 2;
        double hh = RoqGeometry.BODY_HEIGHT / 2;
        Path2D.Double body = new Path2D.Double();
        double[][] corners = {{hl, hh}, {-hl, hh}, {-hl, -hh}, {hl, -hh}};
        for (int k = 0; k < 4; k++) {
            double wx = toWorld(s, corners[k][0], 0, corners[k][1], 0);
            double wz = toWorld(s, corners[k][0], 0, corners[k][1], 2);
            if (k == 0) {
                body.moveTo(ox + wx * scale, oy - wz * scale);
            } else {
                body.lineTo(ox + wx * scale, oy - wz * scale);
            }
        }
        body.closePath();
        for (int l = 0; l < RoqGeometry.LEGS; l++) {
            legInWorld(s, l);
            drawLeg(g, s, l, ox, oy, scale, 0, 2);
        }
        g.setColor(BODY);
        g.fill(body);
        g.setColor(LEG);
        g.draw(body);
        mark(g, ox + s.groundTruthCentreOfMass(0) * scale, oy - s.groundTruthCentreOfMass(2) * scale);
        g.setClip(clip);
    }

    // ---- sensor panel ----------------------------------------------------------------------------------------

    private void paintPanel(Graphics2D g, SensorSnapshot s, Rectangle r) {
        g.setColor(Color.WHITE);
        g.fill(r);
        g.setColor(LEG);
        g.setFont(FONT);
        int x = r.x + 10;
        int y = r.y + 18;
        int dy = 16;
        String[] lines = {
                String.format(Locale.ROOT, "t %.3f s  tick %d", s.simTime(), s.tick()),
                String.format(Locale.ROOT, "roll %+.1f°  pitch %+.1f°", Math.toDegrees(s.roll()), Math.toDegrees(s.pitch())),
                "soles (N):",
                String.format(Locale.ROOT, " FL %5.1f  FR %5.1f", s.footForce(0), s.footForce(1)),
                String.format(Locale.ROOT, " HL %5.1f  HR %5.1f", s.footForce(2), s.footForce(3)),
                String.format(Locale.ROOT, "IR %.2f m  sonar %.2f m", s.irRange(), s.ultrasonicRange()),
                String.format(Locale.ROOT, "broken cells %d", s.brokenCellCount()),
                "ground truth:",
                String.format(Locale.ROOT, " body %.2f %.2f %.2f", s.groundTruthBodyPosition(0),
                        s.groundTruthBodyPosition(1), s.groundTruthBodyPosition(2)),
                String.format(Locale.ROOT, " CoM  %.2f %.2f %.2f", s.groundTruthCentreOfMass(0),
                        s.groundTruthCentreOfMass(1), s.groundTruthCentreOfMass(2)),
                "depth image (near = dark):"};
        for (String line : lines) {
            g.drawString(line, x, y);
            y += dy;
        }
        int px = Math.max(2, Math.min(7, (r.width - 20) / RoqGeometry.DEPTH_WIDTH));
        for (int row = 0; row < RoqGeometry.DEPTH_HEIGHT; row++) {
            for (int col = 0; col < RoqGeometry.DEPTH_WIDTH; col++) {
                double f = Math.min(1, s.depth(col, row) / RoqGeometry.DEPTH_MAX_RANGE);
                int v = (int) (40 + 215 * f);
                g.setColor(new Color(v, v, v));
                g.fillRect(x + col * px, y - 8 + row * px, px, px);
            }
        }
        g.setColor(LEG);
        g.drawRect(x, y - 8, RoqGeometry.DEPTH_WIDTH * px, RoqGeometry.DEPTH_HEIGHT * px);
    }
}
