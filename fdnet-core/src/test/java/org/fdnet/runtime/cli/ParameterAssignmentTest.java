package org.fdnet.runtime.cli;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.junit.jupiter.api.Test;

class ParameterAssignmentTest {
    private static final Path ARMS = Path.of("..", "networks", "arms.fdn");
    private static final NodeRef HEARTBEAT = NodeRef.parse("Heartbeat", "main");

    @Test
    void shouldReadModuleNodeNameAndValueWithMainForABareNode() {
        ParameterAssignment a = ParameterAssignment.parse("Gait/crawl:rise=0.25");
        assertThat(a.node()).isEqualTo(NodeRef.parse("crawl", "Gait"));
        assertThat(a.name()).isEqualTo("rise");
        assertThat(a.value()).isEqualTo("0.25");
        assertThat(ParameterAssignment.parse("Heartbeat:waveform=a=b").value()).isEqualTo("a=b");
        assertThat(ParameterAssignment.parse("Heartbeat:period=5").node()).isEqualTo(HEARTBEAT);
    }

    @Test
    void shouldRefuseTextWithoutNodeNameOrValue() {
        for (String bad : new String[] {"crawl=1", ":rise=1", "Gait/crawl:=1", "Gait/crawl:rise"}) {
            assertThatThrownBy(() -> ParameterAssignment.parse(bad)).as(bad)
                    .hasMessage("expected MODULE/NODE:NAME=VALUE");
        }
    }

    @Test
    void shouldSetTheParameterInTheDefinitionKeepingItsTypeAndTheOthers() throws Exception {
        NetworkInfo arms = NetworkRepository.load(ARMS);
        int before = arms.node(HEARTBEAT).parameters().size();
        ParameterAssignment.parse("Heartbeat:amplitude=2.5").applyTo(arms);
        assertThat(arms.node(HEARTBEAT).parameters()).hasSize(before)
                .contains(new Parameter("amplitude", ParameterType.DOUBLE, "2.5"))
                .contains(new Parameter("period", ParameterType.LONG, "20"));
    }

    @Test
    void shouldNameTheMissingNodeOrParameter() throws Exception {
        NetworkInfo arms = NetworkRepository.load(ARMS);
        assertThatThrownBy(() -> ParameterAssignment.parse("Nobody:x=1").applyTo(arms))
                .hasMessageContaining("no node").hasMessageContaining("Nobody");
        assertThatThrownBy(() -> ParameterAssignment.parse("Heartbeat:nothing=1").applyTo(arms))
                .hasMessageContaining("Heartbeat").hasMessageContaining("no parameter nothing");
    }
}
