package org.fdnet.hi.graph;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.geom.AffineTransform;
import java.awt.geom.NoninvertibleTransformException;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.LinkedHashSet;
import java.util.Set;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;
import org.fdnet.netinfo.NodeRef;

/**
 * The graphic panel: ONE component painting the whole scene (no component per node), so a thousand nodes
 * stay fluid. Left button: click selects (Shift/Ctrl adds), drag moves the selection, drag on empty space
 * draws a rubber band; right or middle drag pans; the wheel zooms around the pointer; double-click opens a
 * node; right click asks for the context menu.
 */
public final class GraphCanvas extends JComponent implements SceneListener {
    private static final double MIN_ZOOM = 0.1;
    private static final double MAX_ZOOM = 4;

    private final GraphScene scene;
    private final GraphPainter painter;
    private double zoom = 1;
    private double panX;
    private double panY;
    private Rectangle2D rubberBand;
    private final DragBackdrop backdrop = new DragBackdrop();
    private Font namesFont = Java2DSketch.PLAIN;
    private Consumer<NodeRef> onActivate = ref -> { };
    private BiConsumer<Point, NodeRef> onPopup = (p, ref) -> { };

    public GraphCanvas(GraphScene scene) {
        this.scene = scene;
        this.painter = new GraphPainter(scene);
        setOpaque(true);
        setBackground(Color.WHITE);
        setPreferredSize(new Dimension(900, 600));
        setFocusable(true);
        scene.addListener(this);
        Mouse mouse = new Mouse();
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
    }

    public void onActivate(Consumer<NodeRef> action) {
        onActivate = action;
    }

    public void onPopup(BiConsumer<Point, NodeRef> action) {
        onPopup = action;
    }

    public GraphScene scene() {
        return scene;
    }

    public double zoom() {
        return zoom;
    }

    public void setZoom(double newZoom) {
        zoomAround(new Point2D.Double(getWidth() / 2.0, getHeight() / 2.0), newZoom);
    }

    /** Zooms and pans so the whole drawing fits the panel. */
    public void fit() {
        Rectangle2D e = scene.extent();
        if (e.isEmpty() || getWidth() == 0) {
            return;
        }
        zoom = clamp(Math.min((getWidth() - 40) / e.getWidth(), (getHeight() - 40) / e.getHeight()));
        zoom = Math.min(zoom, 1.5);
        panX = (getWidth() - e.getWidth() * zoom) / 2 - e.getX() * zoom;
        panY = (getHeight() - e.getHeight() * zoom) / 2 - e.getY() * zoom;
        repaint();
    }

    /** Pans so that {@code ref} is in the middle of the panel. */
    public void reveal(NodeRef ref) {
        Rectangle2D b = scene.bounds(ref);
        if (b != null) {
            panX = getWidth() / 2.0 - b.getCenterX() * zoom;
            panY = getHeight() / 2.0 - b.getCenterY() * zoom;
            repaint();
        }
    }

    public AffineTransform transform() {
        AffineTransform t = AffineTransform.getTranslateInstance(panX, panY);
        t.scale(zoom, zoom);
        return t;
    }

    /** The font names are drawn in (one that draws every name: see HiWindow). */
    public Font namesFont() {
        return namesFont;
    }

    public void setNamesFont(Font font) {
        namesFont = font;
        repaint();
    }

    @Override
    protected void paintComponent(Graphics graphics) {
        Graphics2D g = (Graphics2D) graphics.create();
        try {
            Rectangle clip = g.getClipBounds();
            AffineTransform t = transform();
            Rectangle2D modelClip = clip == null ? null : inverse(t).createTransformedShape(clip).getBounds2D();
            boolean smooth = zoom >= GraphPainter.LABEL_SCALE;
            if (dragging()) {
                backdrop.copyTo(g, scene.stillRevision(), t, getWidth(), getHeight(), getBackground(), still -> {
                    still.transform(t);
                    painter.paint(new Java2DSketch(still, smooth, namesFont), null, zoom, GraphPainter.Layer.STILL);
                });
                g.transform(t);
                painter.paint(new Java2DSketch(g, smooth, namesFont), modelClip, zoom, GraphPainter.Layer.MOVING);
            } else {
                backdrop.clear();
                g.setColor(getBackground());
                g.fillRect(0, 0, getWidth(), getHeight());
                g.transform(t);
                painter.paint(new Java2DSketch(g, smooth, namesFont), modelClip, zoom);
            }
            if (rubberBand != null) {
                g.setColor(new Color(0x1F6FEB));
                g.setStroke(new BasicStroke((float) (1 / zoom)));
                g.draw(rubberBand);
                g.setColor(new Color(0x1F, 0x6F, 0xEB, 30));
                g.fill(rubberBand);
            }
        } finally {
            g.dispose();
        }
    }

    /**
     * The selected nodes have moved since anything else changed: the frame is the backdrop of what stays, with the
     * selection and its connections painted over it.
     */
    private boolean dragging() {
        return !scene.selection().isEmpty() && scene.revision() != scene.stillRevision();
    }

    /** Whether the last frame was painted over a drag backdrop (for tests). */
    boolean paintedOverBackdrop() {
        return backdrop.held();
    }

    @Override
    public void sceneChanged() {
        repaint();
    }

    @Override
    public void selectionChanged() {
        repaint();
    }

    @Override
    public void valuesChanged() {
        repaint();
    }

    Point2D toModel(Point p) {
        return inverse(transform()).transform(p, null);
    }

    private static AffineTransform inverse(AffineTransform t) {
        try {
            return t.createInverse();
        } catch (NoninvertibleTransformException e) {
            throw new IllegalStateException("zoom is never 0", e);
        }
    }

    private void zoomAround(Point2D screen, double newZoom) {
        double z = clamp(newZoom);
        double mx = (screen.getX() - panX) / zoom;
        double my = (screen.getY() - panY) / zoom;
        zoom = z;
        panX = screen.getX() - mx * zoom;
        panY = screen.getY() - my * zoom;
        repaint();
    }

    private static double clamp(double z) {
        return Math.max(MIN_ZOOM, Math.min(MAX_ZOOM, z));
    }

    /** Mouse gestures; model coordinates for everything that touches the scene. */
    private final class Mouse extends MouseAdapter {
        private Point2D lastModel;
        private Point lastScreen;
        private Point pressScreen;
        private NodeRef pressedOn;
        private boolean dragged;
        private Point2D bandStart;
        private boolean panning;

        @Override
        public void mousePressed(MouseEvent e) {
            requestFocusInWindow();
            lastScreen = e.getPoint();
            pressScreen = e.getPoint();
            lastModel = toModel(e.getPoint());
            if (!SwingUtilities.isLeftMouseButton(e)) {
                panning = true;
                return;
            }
            boolean adding = e.isShiftDown() || e.isControlDown();
            NodeRef hit = scene.nodeAt(lastModel);
            pressedOn = adding ? null : hit;
            dragged = false;
            if (hit != null) {
                if (adding) {
                    scene.toggle(hit);
                } else if (!scene.selection().contains(hit)) {
                    scene.select(Set.of(hit));
                }
                return;
            }
            ConnectionRef c = scene.connectionAt(lastModel, 5 / zoom);
            if (c != null) {
                scene.selectConnection(c);
                return;
            }
            if (!adding) {
                scene.select(Set.of());
            }
            bandStart = lastModel;
        }

        @Override
        public void mouseDragged(MouseEvent e) {
            Point2D now = toModel(e.getPoint());
            dragged = true;
            if (panning) {
                panX += e.getX() - lastScreen.x;
                panY += e.getY() - lastScreen.y;
                repaint();
            } else if (bandStart != null) {
                rubberBand = new Rectangle2D.Double(Math.min(bandStart.getX(), now.getX()),
                        Math.min(bandStart.getY(), now.getY()), Math.abs(now.getX() - bandStart.getX()),
                        Math.abs(now.getY() - bandStart.getY()));
                repaint();
            } else if (!scene.selection().isEmpty()) {
                scene.moveSelected(now.getX() - lastModel.getX(), now.getY() - lastModel.getY());
            }
            lastScreen = e.getPoint();
            lastModel = now;
        }

        @Override
        public void mouseReleased(MouseEvent e) {
            if (rubberBand != null) {
                Set<NodeRef> caught = new LinkedHashSet<>(scene.selection());
                for (NodeRef ref : scene.visibleNodes()) {
                    Rectangle2D b = scene.bounds(ref);
                    if (b != null && rubberBand.intersects(b)) {
                        caught.add(ref);
                    }
                }
                scene.select(caught);
            }
            if (!dragged && pressedOn != null && scene.selection().size() > 1) {
                scene.select(Set.of(pressedOn));
            }
            pressedOn = null;
            scene.endMove();
            boolean clickedRight = panning && pressScreen != null && e.getPoint().distance(pressScreen) < 4
                    && SwingUtilities.isRightMouseButton(e);
            rubberBand = null;
            bandStart = null;
            panning = false;
            repaint();
            if (clickedRight) {
                NodeRef hit = scene.nodeAt(toModel(e.getPoint()));
                if (hit != null && !scene.selection().contains(hit)) {
                    scene.select(Set.of(hit));
                }
                onPopup.accept(e.getPoint(), hit);
            }
        }

        @Override
        public void mouseClicked(MouseEvent e) {
            if (e.getClickCount() == 2 && SwingUtilities.isLeftMouseButton(e)) {
                NodeRef hit = scene.nodeAt(toModel(e.getPoint()));
                if (hit != null) {
                    onActivate.accept(hit);
                }
            }
        }

        @Override
        public void mouseWheelMoved(MouseWheelEvent e) {
            zoomAround(e.getPoint(), zoom * Math.pow(1.1, -e.getPreciseWheelRotation()));
        }
    }
}
