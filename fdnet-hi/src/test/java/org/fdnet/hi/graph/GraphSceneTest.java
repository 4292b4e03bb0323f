package org.fdnet.hi.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.Set;
import org.fdnet.hi.edit.UndoableNetworkEditor;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.layout.NodeLayout;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.LayoutRepository;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** What the graphic panel shows, without a display: places, visibility, highlight, hits, selection, SVG. */
class GraphSceneTest {
    private static final Path ROQ = Path.of("..", "networks", "roq-motion.fdn");
    private static final NodeRef JUDGE = new NodeRef("Integration", "judge");
    private static final NodeRef WALK = new NodeRef("Walk", "walk");

    private NetworkInfo network;
    private NetworkLayout layout;
    private UndoableNetworkEditor editor;
    private GraphScene scene;

    @BeforeEach
    void open() throws Exception {
        network = NetworkRepository.load(ROQ);
        layout = LayoutRepository.load(LayoutRepository.sideFileOf(ROQ));
        editor = new UndoableNetworkEditor(network, layout);
        scene = new GraphScene(editor);
    }

    @Test
    void shouldLayOutEveryNodeOfANetworkWithoutFdgWithoutOverlaps() {
        GraphScene fresh = new GraphScene(new UndoableNetworkEditor(network, new NetworkLayout()));
        var nodes = fresh.visibleNodes();
        assertThat(nodes).hasSize(15).allSatisfy(r -> assertThat(fresh.bounds(r)).isNotNull());
        for (NodeRef a : nodes) {
            for (NodeRef b : nodes) {
                if (!a.equals(b)) {
                    assertThat(fresh.bounds(a).intersects(fresh.bounds(b))).as(a + " overlaps " + b).isFalse();
                }
            }
        }
    }

    @Test
    void shouldPlaceANewConnectedNodeAndKeepEveryPositionTheUserSet() {
        NetworkLayout before = copyOfPlaces();
        editor.addNode("Integration", NodeInfo.data("verdict", "org.fdnet.runtime.library.DoubleData"));
        NodeRef verdict = new NodeRef("Integration", "verdict");
        assertThat(scene.bounds(verdict)).isNotNull();
        editor.addConnection("Integration", ConnectionInfo.writer(JUDGE, verdict));
        for (var m : before.modules()) {
            m.nodes().forEach((name, at) -> assertThat(layout.node(new NodeRef(m.name(), name))).isEqualTo(at));
        }
    }

    @Test
    void shouldHideAndShowAModuleInOneCallAndKeepItsConnectionsOutWhileHidden() {
        scene.setModuleVisible("Walk", false);
        assertThat(scene.visibleNodes()).noneMatch(r -> r.module().equals("Walk"));
        assertThat(scene.visibleConnections()).noneMatch(c -> c.connection().touches(WALK));
        assertThat(scene.layoutChanged()).isTrue();
        scene.setModuleVisible("Walk", true);
        assertThat(scene.visibleNodes()).contains(WALK);
    }

    @Test
    void shouldHighlightExactlyTheAncestorsOrDescendantsTheNetworkReports() {
        scene.highlight(JUDGE, GraphScene.Relatives.ANCESTORS);
        assertThat(scene.highlighted()).containsAll(network.ancestors(JUDGE)).contains(JUDGE)
                .hasSize(network.ancestors(JUDGE).size() + (network.ancestors(JUDGE).contains(JUDGE) ? 0 : 1));
        scene.highlight(JUDGE, GraphScene.Relatives.DESCENDANTS);
        assertThat(scene.highlighted()).containsAll(network.descendants(JUDGE)).doesNotContainAnyElementsOf(
                network.ancestors(JUDGE).stream().filter(r -> !network.descendants(JUDGE).contains(r) && !r.equals(JUDGE)).toList());
    }

    @Test
    void shouldFindTheNodeAndTheConnectionUnderThePointer() {
        var b = scene.bounds(JUDGE);
        assertThat(scene.nodeAt(new java.awt.geom.Point2D.Double(b.getCenterX(), b.getCenterY()))).isEqualTo(JUDGE);
        ConnectionRef any = scene.visibleConnections().get(0);
        var s = scene.segment(any.connection());
        var middle = new java.awt.geom.Point2D.Double((s.getX1() + s.getX2()) / 2, (s.getY1() + s.getY2()) / 2);
        assertThat(scene.connectionAt(middle, 3).connection().sameLink(any.connection())
                || scene.segment(scene.connectionAt(middle, 3).connection()).ptSegDist(middle) < 0.01).isTrue();
    }

    @Test
    void shouldMoveOnlySelectedNodesAndNeverTheNetwork() {
        NetworkInfo before = network.copy();
        NodeLayout walkBefore = layout.node(WALK);
        scene.select(Set.of(JUDGE));
        var judgeBefore = scene.bounds(JUDGE);
        scene.moveSelected(15, -5);
        assertThat(scene.bounds(JUDGE).getX()).isEqualTo(judgeBefore.getX() + 15);
        assertThat(layout.node(WALK)).isEqualTo(walkBefore);
        assertThat(network).isEqualTo(before);
        assertThat(editor.canUndo()).isFalse();
    }

    @Test
    void shouldDropADeletedNodeFromTheSelectionAndGetItsPlaceBackOnUndo() {
        scene.select(Set.of(JUDGE));
        var place = scene.bounds(JUDGE);
        editor.deleteNode(JUDGE);
        assertThat(scene.selection()).isEmpty();
        editor.undo();
        assertThat(scene.bounds(JUDGE)).isEqualTo(place);
    }

    @Test
    void shouldExportAnSvgWithEveryVisibleNodeName() {
        SvgSketch svg = new SvgSketch(0, 0);
        new GraphPainter(scene).paint(svg, null);
        String doc = svg.document(100, 100);
        assertThat(doc).startsWith("<?xml").contains("<svg").endsWith("</svg>\n");
        for (NodeRef ref : scene.visibleNodes()) {
            assertThat(doc).contains(">" + ref.node() + "</text>");
        }
    }

    private NetworkLayout copyOfPlaces() {
        NetworkLayout copy = new NetworkLayout();
        for (var m : layout.modules()) {
            m.nodes().forEach((name, at) -> copy.put(new NodeRef(m.name(), name), at));
        }
        return copy;
    }
}
