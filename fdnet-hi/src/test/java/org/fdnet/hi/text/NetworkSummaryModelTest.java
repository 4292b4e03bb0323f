package org.fdnet.hi.text;

import static org.assertj.core.api.Assertions.assertThat;

import org.fdnet.hi.speedy.SpeedyDesign;
import org.fdnet.netinfo.ModuleCounts;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.junit.jupiter.api.Test;

class NetworkSummaryModelTest {
    private final NetworkInfo network = SampleNetwork.create();
    private final NetworkSummaryModel model = new NetworkSummaryModel(new PlainNetworkEditor(network), new SpeedyDesign());

    @Test
    void shouldShowEachModuleInNumbersAndTheTotal() {
        assertThat(model.networkName()).isEqualTo("robot");
        assertThat(model.moduleRows()).containsExactly(
                new NetworkSummaryModel.ModuleRow("main", true, new ModuleCounts(2, 1, 1, 1)),
                new NetworkSummaryModel.ModuleRow("Arm", false, new ModuleCounts(1, 1, 2, 0)));
        assertThat(model.total()).isEqualTo(new ModuleCounts(3, 2, 3, 1));
    }

    @Test
    void shouldRecountWhenTheNetworkChangesElsewhere() {
        network.addNode("Arm", NodeInfo.data("Wrist", "fdnet.Wrist"));

        assertThat(model.moduleRows().get(1).counts()).isEqualTo(new ModuleCounts(2, 1, 2, 0));
        assertThat(model.total().datas()).isEqualTo(4);
    }

    @Test
    void shouldAddAModuleAndTurnNewIntoEditForAnExistingName() {
        model.typeModuleName("Leg");
        model.chooseLoadAtStart(false);
        assertThat(model.saveLabel()).isEqualTo("New");
        assertThat(model.save().accepted()).isTrue();

        assertThat(network.module("Leg").loadAtStart()).isFalse();
        assertThat(model.saveLabel()).isEqualTo("Edit");
        model.chooseLoadAtStart(true);
        assertThat(model.save().accepted()).isTrue();
        assertThat(network.module("Leg").loadAtStart()).isTrue();
    }

    @Test
    void shouldDeleteAModuleAndRefuseToDeleteMain() {
        assertThat(model.delete("main").reason()).contains("cannot be deleted");
        assertThat(model.delete("Arm").accepted()).isTrue();

        assertThat(model.moduleRows()).extracting(NetworkSummaryModel.ModuleRow::name).containsExactly("main");
        assertThat(model.total()).isEqualTo(new ModuleCounts(2, 1, 1, 1));
    }
}
