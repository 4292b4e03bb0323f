package org.fdnet.hi.layout;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;

/** Where ELK puts nodes: a small network as one graph, a large one module by module. */
class ElkLayeredLayoutTest {
    private static final NodeSize SIZE = new NodeSize(120, 40);

    @Test
    void shouldKeepEachModuleOfALargeNetworkInABlockOfItsOwnWithNoNodesOverlapping() {
        NetworkInfo network = chains(6, 60, 0.3);
        Map<NodeRef, Point2D> at = ElkLayeredLayout.positions(network, ref -> SIZE);

        assertThat(at).hasSize(360);
        Map<String, Rectangle2D> blocks = new java.util.HashMap<>();
        at.forEach((ref, p) -> blocks.merge(ref.module(), box(p), Rectangle2D::createUnion));
        for (String a : blocks.keySet()) {
            for (String b : blocks.keySet()) {
                if (!a.equals(b)) {
                    assertThat(blocks.get(a).intersects(blocks.get(b))).as(a + "'s block overlaps " + b + "'s").isFalse();
                }
            }
        }
        List<Rectangle2D> boxes = at.values().stream().map(ElkLayeredLayoutTest::box).toList();
        for (int i = 0; i < boxes.size(); i++) {
            for (int j = i + 1; j < boxes.size(); j++) {
                assertThat(boxes.get(i).intersects(boxes.get(j))).as("nodes %d and %d overlap", i, j).isFalse();
            }
        }
    }

    @Test
    void shouldLetValuesFlowLeftToRightInsideEachModuleAndFromModuleToModule() {
        NetworkInfo network = chains(4, 80, 0);
        network.addConnection("M1", ConnectionInfo.reader(new NodeRef("M0", "d39"), new NodeRef("M1", "r0")));
        network.addConnection("M2", ConnectionInfo.reader(new NodeRef("M1", "d39"), new NodeRef("M2", "r0")));
        Map<NodeRef, Point2D> at = ElkLayeredLayout.positions(network, ref -> SIZE);

        assertThat(at.get(new NodeRef("M0", "d0")).getX()).isLessThan(at.get(new NodeRef("M0", "d39")).getX());
        double m0Right = at.entrySet().stream().filter(e -> e.getKey().module().equals("M0"))
                .mapToDouble(e -> e.getValue().getX()).max().orElseThrow();
        double m1Left = at.entrySet().stream().filter(e -> e.getKey().module().equals("M1"))
                .mapToDouble(e -> e.getValue().getX()).min().orElseThrow();
        assertThat(m1Left).as("M1, which reads M0, lies right of it").isGreaterThan(m0Right);
    }

    @Test
    void shouldLayOutASmallNetworkAsOneGraphSoTheFlowCrossesModules() {
        NetworkInfo network = chains(2, 20, 0);
        network.addConnection("M1", ConnectionInfo.reader(new NodeRef("M0", "d9"), new NodeRef("M1", "r0")));
        network.addConnection("M0", ConnectionInfo.reader(new NodeRef("M1", "d9"), new NodeRef("M0", "r0")));
        Map<NodeRef, Point2D> at = ElkLayeredLayout.positions(network, ref -> SIZE);

        assertThat(ElkLayeredLayout.byModule(network)).isFalse();
        // In one graph M0's chain feeds M1's and M1's feeds M0's: one of them must start right of the other's end.
        double m0Start = at.get(new NodeRef("M0", "r0")).getX();
        double m1End = at.get(new NodeRef("M1", "d9")).getX();
        double m1Start = at.get(new NodeRef("M1", "r0")).getX();
        double m0End = at.get(new NodeRef("M0", "d9")).getX();
        assertThat(m1Start > m0End || m0Start > m1End).as("the two chains continue each other").isTrue();
    }

    /**
     * {@code modules} modules (M0, M1, ...), each a chain r0 → d0 → r1 → d1 ... of {@code perModule} nodes, and
     * a share {@code across} of the Relations also reading a Data of a random other module.
     */
    private static NetworkInfo chains(int modules, int perModule, double across) {
        NetworkInfo network = new NetworkInfo("blocks");
        Random random = new Random(2004);
        List<NodeRef> relations = new ArrayList<>();
        for (int m = 0; m < modules; m++) {
            String module = "M" + m;
            network.addModule(module, true);
            for (int i = 0; i < perModule / 2; i++) {
                NodeRef r = network.addNode(module, NodeInfo.relation("r" + i, "test.R"));
                NodeRef d = network.addNode(module, NodeInfo.data("d" + i, "test.D"));
                relations.add(r);
                network.addConnection(module, ConnectionInfo.writer(r, d));
                if (i > 0) {
                    network.addConnection(module, ConnectionInfo.reader(new NodeRef(module, "d" + (i - 1)), r));
                }
            }
        }
        for (NodeRef r : relations) {
            if (random.nextDouble() < across) {
                String other = "M" + ((Integer.parseInt(r.module().substring(1)) + 1 + random.nextInt(modules - 1)) % modules);
                network.addConnection(r.module(), ConnectionInfo.reader(
                        new NodeRef(other, "d" + random.nextInt(perModule / 2)), r));
            }
        }
        return network;
    }

    private static Rectangle2D box(Point2D p) {
        return new Rectangle2D.Double(p.getX(), p.getY(), SIZE.width(), SIZE.height());
    }
}
