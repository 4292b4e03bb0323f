package org.fdnet.viewer.layout;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.List;
import org.fdnet.viewer.data.NodeSelection;
import org.fdnet.viewer.data.Series;
import org.fdnet.viewer.data.UnitBook;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class LayoutFileTest {
    @TempDir
    Path folder;

    @Test
    void shouldWriteALayoutAndReadTheSameBack() throws Exception {
        ViewerLayout layout = new ViewerLayout(List.of(
                new PlotSpec("Sole forces", List.of(new NodeSelection("main/foot forces", "N"))),
                new PlotSpec("Track", List.of(new NodeSelection("Course/track[0]", "m"), new NodeSelection("Course/track[1]", "m"))),
                new PlotSpec("Phase", List.of(new NodeSelection("main/gait phase[0]", "")))), 12.5, false);
        Path file = folder.resolve("desk.layout");
        LayoutFile.write(layout, file);
        assertThat(LayoutFile.read(file)).isEqualTo(layout);
    }

    @Test
    void shouldRefuseABadLineNamingTheFileAndTheLine() {
        assertThatThrownBy(() -> LayoutFile.parse("window 10\n  main/attitude[rad]\n", "desk.layout"))
                .hasMessage("desk.layout:2: a series before any 'plot TITLE' line: 'main/attitude[rad]'");
        assertThatThrownBy(() -> LayoutFile.parse("plot A\nlegend aside\n", "desk.layout"))
                .hasMessage("desk.layout:2: 'legend' takes 'beside' or 'hidden', was 'aside'");
        assertThatThrownBy(() -> LayoutFile.parse("window soon\nplot A\n", "desk.layout"))
                .hasMessageStartingWith("desk.layout:1: 'window' takes seconds");
        assertThatThrownBy(() -> LayoutFile.parse("# nothing\n", "desk.layout")).hasMessageContaining("no 'plot TITLE' line");
    }

    @Test
    void shouldTellAComponentIndexFromAUnit() {
        assertThat(NodeSelection.parse("Course/track[0]")).isEqualTo(new NodeSelection("Course/track[0]", ""));
        assertThat(NodeSelection.parse("Course/track[0][m]")).isEqualTo(new NodeSelection("Course/track[0]", "m"));
        assertThat(NodeSelection.parse("Course/track[0]").node()).isEqualTo("Course/track");
        assertThat(NodeSelection.parse("Course/track").matches(new Series("Course/track[2]", ""))).isTrue();
        assertThat(NodeSelection.parse("Course/track[0]").matches(new Series("Course/track[2]", ""))).isFalse();
        assertThat(NodeSelection.parse("Course/tr").matches(new Series("Course/track", ""))).isFalse();
    }

    @Test
    void shouldGiveAComponentItsOwnUnitElseItsNodes() {
        UnitBook units = new UnitBook();
        units.learn(new NodeSelection("Course/track", "m"));
        units.learn(new NodeSelection("Course/track[2]", "rad"));
        assertThat(units.unitOf("Course/track[0]", "")).isEqualTo("m");
        assertThat(units.unitOf("Course/track[2]", "")).isEqualTo("rad");
        assertThat(units.unitOf("main/attitude", "?")).isEqualTo("?");
    }

    @Test
    void shouldOfferRoqsLayoutOnlyForARunHoldingItsDatas() {
        List<String> roq = List.of("main/attitude", "main/foot forces", "Balance/margin", "main/gait phase", "Course/track",
                "main/joint angles");
        assertThat(ReadyLayouts.forNodes(roq)).get().extracting(l -> l.plots().size()).isEqualTo(5);
        assertThat(ReadyLayouts.forNodes(List.of("main/attitude", "Pose/pitch"))).isEmpty();
        assertThat(ReadyLayouts.shipped("roq.layout").plots().get(1).series())
                .containsExactly(new NodeSelection("main/foot forces", "N"));
    }
}
