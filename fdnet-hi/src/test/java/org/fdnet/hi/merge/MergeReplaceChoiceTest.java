package org.fdnet.hi.merge;

import static org.assertj.core.api.Assertions.assertThat;

import org.fdnet.hi.text.PlainNetworkEditor;
import org.fdnet.hi.text.SampleNetwork;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.MergePolicy;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.junit.jupiter.api.Test;

class MergeReplaceChoiceTest {
    private final NetworkInfo network = SampleNetwork.create();
    private final PlainNetworkEditor editor = new PlainNetworkEditor(network);
    /** SpeedV2 (Data, one parameter, read by Servo2) is to be renamed Speed, which main already has. */
    private final NodeRef speedV2 = new NodeRef("main", "SpeedV2");

    MergeReplaceChoiceTest() {
        network.addNode("main", NodeInfo.data("SpeedV2", "fdnet.SpeedV2", Parameter.named("gain", "9"),
                Parameter.of("slow")));
        network.addNode("main", NodeInfo.relation("Logger", "fdnet.Logger"));
        network.addConnection("main", ConnectionInfo.reader(speedV2, new NodeRef("main", "Logger")));
    }

    private MergeReplaceChoice choice() {
        return new MergeReplaceChoice(editor, speedV2, "Speed");
    }

    @Test
    void shouldReplaceTheExistingNodeAndKeepOnlyTheIncomingNodesConnections() {
        assertThat(choice().apply(MergeReplaceChoice.Action.REPLACE, null).accepted()).isTrue();

        assertThat(network.node(speedV2)).isNull();
        assertThat(network.node(SampleNetwork.SPEED).className()).isEqualTo("fdnet.SpeedV2");
        assertThat(network.connectionsOf(SampleNetwork.SPEED)).extracting(l -> l.connection().relation())
                .containsExactly(new NodeRef("main", "Logger"));
    }

    @Test
    void shouldMergeKeepingTheExistingNodesParametersWithFirst() {
        assertThat(choice().apply(MergeReplaceChoice.Action.MERGE, MergePolicy.FIRST).accepted()).isTrue();

        NodeInfo speed = network.node(SampleNetwork.SPEED);
        assertThat(speed.className()).isEqualTo("fdnet.SpeedData");
        assertThat(speed.parameter("gain")).isEqualTo("3");
        assertThat(speed.parameters()).hasSize(2);
        assertThat(network.node(speedV2)).isNull();
        assertThat(network.connectionsOf(SampleNetwork.SPEED)).hasSize(3);
    }

    @Test
    void shouldMergeKeepingTheIncomingNodesParametersWithSecond() {
        choice().apply(MergeReplaceChoice.Action.MERGE, MergePolicy.SECOND);

        assertThat(network.node(SampleNetwork.SPEED).parameters())
                .containsExactly(Parameter.named("gain", "9"), Parameter.of("slow"));
    }

    @Test
    void shouldMergeKeepingBothWithoutDuplicatingANamedParameter() {
        choice().apply(MergeReplaceChoice.Action.MERGE, MergePolicy.BOTH);

        assertThat(network.node(SampleNetwork.SPEED).parameters()).extracting(Parameter::value)
                .containsExactly("3", "fast", "slow");
    }

    @Test
    void shouldRefuseToMergeADataWithARelationButStillOfferReplace() {
        MergeReplaceChoice c = new MergeReplaceChoice(editor, new NodeRef("main", "Logger"), "Speed");

        assertThat(c.whyNotMerge()).contains("only two nodes of one kind can merge");
        assertThat(c.apply(MergeReplaceChoice.Action.MERGE, MergePolicy.BOTH).accepted()).isFalse();
        assertThat(network.node(new NodeRef("main", "Logger"))).isNotNull();
        assertThat(c.whyNot()).isNull();
    }

    @Test
    void shouldSayWhenTheNameIsFreeAgain() {
        network.deleteNode(SampleNetwork.SPEED);

        assertThat(choice().whyNot()).isEqualTo("no node is named main/Speed any more: rename main/SpeedV2 directly");
    }
}
