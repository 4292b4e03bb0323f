package org.fdnet.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** bench load's cold figures: a fresh child JVM loads the file once and reports what it measured. */
@Timeout(180)
class ColdLoadProbeTest {
    @TempDir
    Path dir;

    @Test
    void shouldLoadTheFileInAFreshJvmAndReachWhatThisJvmReaches() throws Exception {
        NetworkInfo network = new NetworkGenerator(7, false).generate(2, 60, 100);
        Path file = dir.resolve("small.fdn");
        NetworkRepository.save(network, file);
        NodeRef root = firstData(network);
        int reached = NetworkRepository.load(file).descendants(root).size();

        FreshJvmRun run = FreshJvmRun.of("cold probe", List.of("bench", "load", "cold-probe", "--root", root.toString(),
                file.toString()), ColdLoadProbe.MARKER);
        ColdLoadProbe.Figures figures = ColdLoadProbe.Figures.parse(run.line(ColdLoadProbe.MARKER));

        assertThat(figures.reached()).isEqualTo(reached);
        assertThat(figures.loadMillis()).isPositive();
        assertThat(figures.descendantsMillis()).isPositive();
        assertThat(run.wallMillis()).as("the whole process includes its load").isGreaterThan(figures.loadMillis());
    }

    @Test
    void shouldTimeABareParseInAFreshJvmWithoutAQuery() throws Exception {
        NetworkInfo network = new NetworkGenerator(8, false).generate(1, 20, 30);
        Path file = dir.resolve("bare.fdn");
        NetworkRepository.save(network, file);

        FreshJvmRun run = FreshJvmRun.of("cold bare parse", List.of("bench", "load", "cold-probe", "--bare",
                file.toString()), ColdLoadProbe.MARKER);
        ColdLoadProbe.Figures figures = ColdLoadProbe.Figures.parse(run.line(ColdLoadProbe.MARKER));

        assertThat(figures.loadMillis()).isPositive();
        assertThat(figures.reached()).isEqualTo(-1);
        assertThat(figures.descendantsMillis()).isNaN();
    }

    @Test
    void shouldFailWithTheChildsOutputNamingAMissingFile() {
        Path missing = dir.resolve("missing.fdn");
        assertThat(Files.exists(missing)).isFalse();

        assertThatThrownBy(() -> FreshJvmRun.of("cold probe", List.of("bench", "load", "cold-probe", missing.toString()),
                ColdLoadProbe.MARKER))
                .isInstanceOf(IllegalStateException.class)
                .hasMessageContaining("missing.fdn");
    }

    private static NodeRef firstData(NetworkInfo network) {
        for (ModuleInfo m : network.modules()) {
            for (NodeInfo n : m.nodes()) {
                if (n.kind() == NodeKind.DATA && !network.descendants(new NodeRef(m.name(), n.name())).isEmpty()) {
                    return new NodeRef(m.name(), n.name());
                }
            }
        }
        throw new IllegalStateException("the generated network has no Data with descendants");
    }
}
