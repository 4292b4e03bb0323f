package org.fdnet.hi.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Set;
import org.fdnet.hi.edit.UndoableNetworkEditor;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.LayoutRepository;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** A drag repaints the selection over a backdrop of the rest: the frames must show what a whole repaint shows. */
class DragBackdropTest {
    private static final Path ROQ = Path.of("..", "networks", "roq-motion.fdn");
    private static final NodeRef WALK = new NodeRef("Walk", "walk");
    private static final NodeRef JUDGE = new NodeRef("Integration", "judge");

    private GraphScene scene;
    private GraphCanvas canvas;

    @BeforeEach
    void open() throws Exception {
        scene = new GraphScene(new UndoableNetworkEditor(NetworkRepository.load(ROQ),
                LayoutRepository.load(LayoutRepository.sideFileOf(ROQ))));
        canvas = new GraphCanvas(scene);
        canvas.setSize(900, 600);
        canvas.fit();
        scene.select(Set.of(WALK));
    }

    @Test
    void shouldShowTheDraggedNodeWhereItIsNowAsAWholeRepaintDoes() {
        BufferedImage before = frame();
        scene.moveSelected(40, 25);
        frame();
        scene.moveSelected(-15, 30);
        BufferedImage dragged = frame();
        assertThat(canvas.paintedOverBackdrop()).isTrue();

        BufferedImage whole = wholeRepaint();
        assertThat(canvas.paintedOverBackdrop()).isFalse();
        long stale = differing(before, whole);
        assertThat(stale).as("the move shows in a whole repaint").isGreaterThan(500);
        assertThat(differing(dragged, whole)).as("pixels where the drag frame differs from a whole repaint")
                .isLessThan(stale / 20);
    }

    @Test
    void shouldPaintTheBackdropAfreshWhenSomethingElseChangesDuringADrag() {
        scene.moveSelected(10, 10);
        frame();
        scene.setNodeColour(JUDGE, new Color(0xD02020));
        scene.moveSelected(10, 10);
        BufferedImage dragged = frame();
        assertThat(canvas.paintedOverBackdrop()).isTrue();

        Rectangle2D judge = scene.bounds(JUDGE);
        Point2D inside = canvas.transform().transform(new Point2D.Double(
                judge.getX() + judge.getWidth() * 0.2, judge.getY() + judge.getHeight() * 0.25), null);
        assertThat(new Color(dragged.getRGB((int) inside.getX(), (int) inside.getY())))
                .as("the new colour shows during the drag").isEqualTo(scene.fillColour(JUDGE));
    }

    private BufferedImage frame() {
        BufferedImage image = new BufferedImage(canvas.getWidth(), canvas.getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            canvas.paint(g);
        } finally {
            g.dispose();
        }
        return image;
    }

    /** The drag ends, so the next frame repaints everything. */
    private BufferedImage wholeRepaint() {
        scene.endMove();
        return frame();
    }

    private static long differing(BufferedImage a, BufferedImage b) {
        long n = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                if (a.getRGB(x, y) != b.getRGB(x, y)) {
                    n++;
                }
            }
        }
        return n;
    }
}
