package org.fdnet.netinfo.xml;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.layout.NodeLayout;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class LayoutRepositoryTest {
    @TempDir
    Path dir;

    private Path fdg(String body) {
        return NetworkFiles.file(dir, "net.fdg", "<?xml version=\"1.0\"?>\n<!DOCTYPE fdg SYSTEM \"fdg.dtd\">\n" + body, StandardCharsets.UTF_8);
    }

    @Test
    void shouldLoadTheArmsLayoutBesideItsNetwork() throws Exception {
        Path network = Path.of("../networks/arms.fdn");
        NetworkLayout layout = LayoutRepository.load(LayoutRepository.sideFileOf(network));
        assertThat(layout.module("LeftArm").colour()).isEqualTo("#3C9D5D");
        assertThat(layout.node(new NodeRef("RightArm", "Mirror"))).isEqualTo(new NodeLayout(780, 340, 120.0, 48.0, null));
        assertThat(layout.staleEntries(NetworkRepository.load(network))).isEmpty();
    }

    @Test
    void shouldRoundTripALayout() throws Exception {
        NetworkLayout layout = new NetworkLayout();
        layout.setNetwork("n");
        layout.put(new NodeRef("main", "姿勢"), new NodeLayout(1.5, -2, 80.0, null, "#ABCDEF"));
        layout.moduleOrNew("Arm").setVisible(false);
        layout.moduleOrNew("Arm").setColour("#000000");
        Path file = dir.resolve("out.fdg");
        LayoutRepository.save(layout, file);
        assertThat(LayoutRepository.load(file)).isEqualTo(layout);
    }

    @Test
    void shouldReportABadColourAndANonNumberAtTheirLines() {
        Path file = fdg("<fdg>\n<module name=\"main\" colour=\"red\">\n<node name=\"A\" x=\"1\" y=\"two\"/>\n</module>\n</fdg>");
        assertThatThrownBy(() -> LayoutRepository.load(file)).isInstanceOfSatisfying(NetworkFileException.class, e -> {
            assertThat(e.problems()).extracting(Problem::line).containsExactly(4, 5);
            assertThat(e.problems().get(0).message()).contains("#RRGGBB");
            assertThat(e.problems().get(1).message()).contains("y 'two' is not a number");
        });
    }

    @Test
    void shouldReportLayoutDtdViolations() {
        Path file = fdg("<fdg>\n<module name=\"main\" visible=\"maybe\"><node name=\"A\"/></module>\n</fdg>");
        assertThatThrownBy(() -> LayoutRepository.load(file)).isInstanceOfSatisfying(NetworkFileException.class,
                e -> assertThat(e.problems()).allMatch(p -> p.line() == 4));
    }

    @Test
    void shouldNameEntriesTheNetworkNoLongerHas() throws Exception {
        NetworkInfo network = new NetworkInfo("n");
        network.addNode("main", NodeInfo.data("A", "C"));
        NetworkLayout layout = new NetworkLayout();
        layout.put(new NodeRef("main", "A"), NodeLayout.at(0, 0));
        layout.put(new NodeRef("main", "Gone"), NodeLayout.at(0, 0));
        layout.put(new NodeRef("Arm", "X"), NodeLayout.at(0, 0));
        assertThat(layout.staleEntries(network)).containsExactly("node 'main/Gone'", "module 'Arm'");
    }
}
