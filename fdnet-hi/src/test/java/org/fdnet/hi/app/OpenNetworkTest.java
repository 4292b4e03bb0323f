package org.fdnet.hi.app;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.LayoutRepository;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Opening, saving and searching without a display. */
class OpenNetworkTest {
    private static final Path NETWORKS = Path.of("..", "networks");

    @Test
    void shouldSaveTheNetworkAndOnlyTheLayoutOfNodesThatStillExist(@TempDir Path dir) throws Exception {
        Path fdn = copyRoq(dir);
        OpenNetwork open = OpenNetwork.load(fdn);
        open.editor().deleteNode(new NodeRef("Walk", "walk"));
        assertThat(open.unsaved()).isTrue();
        open.saveAs(fdn);
        assertThat(open.unsaved()).isFalse();
        assertThat(NetworkRepository.load(fdn)).isEqualTo(open.editor().network());
        var saved = LayoutRepository.load(LayoutRepository.sideFileOf(fdn));
        assertThat(saved.staleEntries(open.editor().network())).isEmpty();
        assertThat(saved.node(new NodeRef("Walk", "walk candidate"))).isNotNull();
    }

    @Test
    void shouldTellTheEditorTheFileItsNodePathsAreRelativeTo(@TempDir Path dir) throws Exception {
        Path fdn = copyRoq(dir);
        OpenNetwork open = OpenNetwork.load(fdn);
        assertThat(open.editor().networkFile()).isEqualTo(fdn);
        Path elsewhere = Files.createDirectories(dir.resolve("elsewhere")).resolve("copy.fdn");
        open.saveAs(elsewhere);
        assertThat(open.editor().networkFile()).isEqualTo(elsewhere);
    }

    @Test
    void shouldReportEveryProblemOfABadFileWithItsLineAndColumn(@TempDir Path dir) throws Exception {
        Path bad = dir.resolve("bad.fdn");
        Files.writeString(bad, "<?xml version=\"1.0\"?>\n<cnet name=\"x\">\n  <dstructure>\n    <name>a</name>\n  </dstructure>\n</cnet>\n");
        assertThatThrownBy(() -> OpenNetwork.load(bad)).isInstanceOfSatisfying(NetworkFileException.class,
                e -> assertThat(e.problems()).isNotEmpty().allSatisfy(p -> assertThat(p.line()).isPositive()));
    }

    @Test
    void shouldOpenWithAFreshLayoutWhenTheFdgIsBroken(@TempDir Path dir) throws Exception {
        Path fdn = copyRoq(dir);
        Files.writeString(LayoutRepository.sideFileOf(fdn), "<fdg><module name=\"main\"><node name=\"x\" x=\"oops\" y=\"1\"/></module></fdg>");
        OpenNetwork open = OpenNetwork.load(fdn);
        assertThat(open.layoutWarning()).contains("roq-motion.fdg");
        assertThat(open.scene().visibleNodes()).allSatisfy(r -> assertThat(open.scene().bounds(r)).isNotNull());
    }

    @Test
    void shouldFindNodesByNameClassOrParameter() throws Exception {
        var network = NetworkRepository.load(NETWORKS.resolve("roq-motion.fdn"));
        assertThat(NodeSearch.find(network, "JUDGE")).extracting(NodeRef::node).containsExactly("judge terrain", "judge");
        assertThat(NodeSearch.find(network, "Threshold")).containsExactly(new NodeRef("Integration", "judge terrain"));
        assertThat(NodeSearch.find(network, "movingWeights")).containsExactly(new NodeRef("Integration", "integrate"));
        assertThat(NodeSearch.find(network, "in0 ?")).containsExactly(new NodeRef("Integration", "judge"));
        assertThat(NodeSearch.find(network, "nothing like this")).isEmpty();
    }

    private static Path copyRoq(Path dir) throws Exception {
        Path fdn = dir.resolve("roq-motion.fdn");
        Files.copy(NETWORKS.resolve("roq-motion.fdn"), fdn);
        Files.copy(NETWORKS.resolve("roq-motion.fdg"), dir.resolve("roq-motion.fdg"));
        return fdn;
    }
}
