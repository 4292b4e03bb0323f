package org.fdnet.hi.text;

import static org.assertj.core.api.Assertions.assertThat;

import org.fdnet.hi.speedy.SpeedyDesign;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;

class ConnectionFormModelTest {
    private final NetworkInfo network = SampleNetwork.create();
    private final PlainNetworkEditor editor = new PlainNetworkEditor(network);
    private final ConnectionFormModel arm = new ConnectionFormModel(editor, "Arm", new SpeedyDesign());

    @Test
    void shouldOfferOnlyExistingNodesOfTheRightKindAsThisModuleNamesThem() {
        assertThat(arm.dataChoices()).containsExactly("Angle", "Speed", "Command");
        assertThat(arm.relationChoices()).containsExactly("Servo", "Control");
    }

    @Test
    void shouldNotAcceptAnEndThatIsNotOffered() {
        arm.chooseData("Ghost");
        arm.chooseRelation("Servo");

        assertThat(arm.data()).isNull();
        assertThat(arm.whyNotAdd()).isEqualTo("choose an existing Data");
        assertThat(arm.add().accepted()).isFalse();
        assertThat(network.module("Arm").connections()).hasSize(2);
    }

    @Test
    void shouldAddAWriterBetweenChosenNodes() {
        arm.chooseKind(ConnectionKind.WRITER);
        arm.chooseData("Command");
        arm.chooseRelation("Servo");

        assertThat(arm.add().accepted()).isTrue();
        assertThat(network.module("Arm").connections())
                .contains(ConnectionInfo.writer(SampleNetwork.SERVO, SampleNetwork.COMMAND));
        assertThat(arm.connections()).hasSize(3);
    }

    @Test
    void shouldFollowNodesAddedAndDeletedElsewhere() {
        network.addNode("main", NodeInfo.data("Angle", "fdnet.Angle"));
        assertThat(arm.dataChoices()).as("main's Angle is shadowed by Arm's, so it is written in full")
                .containsExactly("Angle", "Speed", "Command", "main/Angle");

        network.deleteNode(SampleNetwork.SPEED);
        assertThat(arm.dataChoices()).doesNotContain("Speed");
        assertThat(arm.connections()).containsExactly(ConnectionInfo.reader(SampleNetwork.ANGLE, SampleNetwork.SERVO));
    }

    @Test
    void shouldDeleteTheChosenConnectionAndRefuseWhenNoneIsChosen() {
        assertThat(arm.delete(-1).reason()).isEqualTo("choose the connection to delete in the table first");
        assertThat(arm.delete(1).accepted()).isTrue();
        assertThat(network.connectionsOf(SampleNetwork.SPEED)).hasSize(1);
        assertThat(arm.describe(arm.connections().get(0))).isEqualTo("Reader Angle → Servo");
    }

    @Test
    void shouldPassTheNetworksRefusalOfADuplicate() {
        arm.chooseData("Angle");
        arm.chooseRelation("Servo");

        assertThat(arm.add().reason()).contains("duplicate");
        assertThat(network.connectionsOf(new NodeRef("Arm", "Angle"))).hasSize(1);
    }
}
