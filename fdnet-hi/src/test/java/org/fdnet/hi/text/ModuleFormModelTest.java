package org.fdnet.hi.text;

import static org.assertj.core.api.Assertions.assertThat;

import org.fdnet.hi.speedy.SpeedyDesign;
import org.fdnet.netinfo.ModuleCounts;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;

class ModuleFormModelTest {
    private final NetworkInfo network = SampleNetwork.create();
    private final ModuleFormModel arm = new ModuleFormModel(new PlainNetworkEditor(network), "Arm", new SpeedyDesign());

    @Test
    void shouldRenameTheModuleAndSetItsLoadFlagInOneSave() {
        assertThat(arm.whyNotSave()).isEqualTo("nothing changed");
        arm.typeName("LeftArm");
        arm.chooseLoadAtStart(true);

        assertThat(arm.save().accepted()).isTrue();

        assertThat(network.module("LeftArm").loadAtStart()).isTrue();
        assertThat(arm.module()).isEqualTo("LeftArm");
        assertThat(network.module("LeftArm").connections()).extracting(c -> c.relation())
                .containsOnly(new NodeRef("LeftArm", "Servo"));
    }

    @Test
    void shouldListNodesAndCountsAndFollowChangesElsewhere() {
        assertThat(arm.nodes()).extracting(NodeInfo::name).containsExactly("Angle", "Servo");
        assertThat(arm.counts()).isEqualTo(new ModuleCounts(1, 1, 2, 0));

        network.deleteNode(SampleNetwork.SPEED);
        assertThat(arm.counts()).isEqualTo(new ModuleCounts(1, 1, 1, 0));

        network.renameModule("Arm", "RightArm");
        assertThat(arm.module()).isEqualTo("RightArm");
        assertThat(arm.typedName()).isEqualTo("RightArm");

        network.deleteModule("RightArm");
        assertThat(arm.exists()).isFalse();
        assertThat(arm.whyNotSave()).isEqualTo("module 'RightArm' no longer exists");
    }

    @Test
    void shouldDeleteANodeWithItsConnections() {
        assertThat(arm.deleteNode("Servo").accepted()).isTrue();

        assertThat(arm.connections()).isEmpty();
        assertThat(network.connectionsOf(SampleNetwork.SPEED)).hasSize(1);
    }

    @Test
    void shouldRefuseToRenameMain() {
        ModuleFormModel main = new ModuleFormModel(new PlainNetworkEditor(network), "main", new SpeedyDesign());
        main.typeName("core");
        assertThat(main.whyNotSave()).isEqualTo("module 'main' cannot be renamed");
        assertThat(network.module("main")).isNotNull();
    }
}
