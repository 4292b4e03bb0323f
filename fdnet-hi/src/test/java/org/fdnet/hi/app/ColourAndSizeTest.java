package org.fdnet.hi.app;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Color;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.LayoutRepository;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Node and module colour and node size (View menu, thesis Chapter 5): shown on the drawing, kept in the .fdg only
 * (never in the .fdn), and there again after saving and reopening.
 */
class ColourAndSizeTest {
    private static final Path NETWORKS = Path.of("..", "networks");
    private static final NodeRef PLAN = new NodeRef("LeftArm", "Plan");
    private static final NodeRef SERVO = new NodeRef("LeftArm", "Servo");
    private static final NodeRef CLOCK = new NodeRef("main", "Clock");

    @Test
    void shouldDrawSaveAndReopenNodeAndModuleColoursAndNodeSizes(@TempDir Path dir) throws Exception {
        Path fdn = dir.resolve("arms.fdn");
        Files.copy(NETWORKS.resolve("arms.fdn"), fdn);
        Files.copy(NETWORKS.resolve("arms.fdg"), dir.resolve("arms.fdg"));
        Color moduleColour = new Color(0x7B2D8E);
        Color nodeColour = new Color(0xE0C020);

        OpenNetwork open = OpenNetwork.load(fdn);
        GraphScene scene = open.scene();
        scene.setModuleColour("LeftArm", moduleColour);
        scene.setNodeColour(PLAN, nodeColour);
        scene.setNodeSize(CLOCK, 150, 70);
        assertThat(open.unsaved()).as("view changes are changes to save").isTrue();
        assertThat(scene.moduleColour("LeftArm")).isEqualTo(moduleColour);
        assertThat(scene.fillColour(PLAN)).isEqualTo(nodeColour);
        assertThat(scene.fillColour(SERVO)).as("a node without its own colour takes a tint of its module's")
                .isNotEqualTo(scene.fillColour(new NodeRef("RightArm", "Servo")));
        assertThat(scene.bounds(CLOCK).getWidth()).isEqualTo(150);
        assertThat(scene.bounds(CLOCK).getHeight()).isEqualTo(70);
        assertThat(pixelInside(scene, PLAN, dir.resolve("before.png"))).isEqualTo(nodeColour.getRGB());

        open.saveAs(fdn);
        assertThat(NetworkRepository.load(fdn)).as("the .fdn holds no view state")
                .isEqualTo(NetworkRepository.load(NETWORKS.resolve("arms.fdn")));
        assertThat(Files.readString(dir.resolve("arms.fdg"))).contains("#7B2D8E", "#E0C020");

        GraphScene reopened = OpenNetwork.load(fdn).scene();
        assertThat(reopened.moduleColour("LeftArm")).isEqualTo(moduleColour);
        assertThat(reopened.fillColour(PLAN)).isEqualTo(nodeColour);
        assertThat(reopened.bounds(CLOCK).getWidth()).isEqualTo(150);
        assertThat(reopened.bounds(CLOCK).getHeight()).isEqualTo(70);
        assertThat(LayoutRepository.load(dir.resolve("arms.fdg")).node(CLOCK).width()).isEqualTo(150);
        assertThat(pixelInside(reopened, PLAN, dir.resolve("after.png"))).isEqualTo(nodeColour.getRGB());
    }

    /** The colour painted just inside the node's left edge, at mid height (clear of its name). */
    private static int pixelInside(GraphScene scene, NodeRef ref, Path png) throws Exception {
        GraphExport.png(scene, png);
        BufferedImage image = ImageIO.read(png.toFile());
        Rectangle2D extent = scene.extent();
        Rectangle2D b = scene.bounds(ref);
        double margin = (image.getWidth() - extent.getWidth()) / 2;
        int x = (int) Math.round(b.getX() - extent.getX() + margin + 6);
        int y = (int) Math.round(b.getCenterY() - extent.getY() + margin);
        return image.getRGB(x, y) | 0xFF000000;
    }
}
