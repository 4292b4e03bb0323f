package org.fdnet.netinfo;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

class NestedModulesTest {

    /** Arm (start) holds Hand (with its parent) holding Fingers (on request), and Wrist (on request). */
    private static NetworkInfo arm() {
        NetworkInfo n = new NetworkInfo("arm");
        n.addNode("main", NodeInfo.data("Clock", "D"));
        n.addModule("Arm", true);
        n.addModule("Arm/Hand", true);
        n.addModule("Arm/Hand/Fingers", false);
        n.addModule("Arm/Wrist", false);
        n.addNode("Arm", NodeInfo.data("Grip", "D"));
        n.addNode("Arm/Hand", NodeInfo.data("Grip", "D"));
        n.addNode("Arm/Hand", NodeInfo.relation("Close", "R"));
        n.addNode("Arm/Hand/Fingers", NodeInfo.relation("Curl", "R"));
        n.addConnection("Arm/Hand/Fingers", ConnectionInfo.reader(new NodeRef("Arm/Hand", "Grip"),
                new NodeRef("Arm/Hand/Fingers", "Curl")));
        return n;
    }

    @Test
    void shouldNameNodesOfNestedModulesByPath() {
        NodeRef ref = NodeRef.parse("Arm/Hand/Grip", "main");
        assertThat(ref.module()).isEqualTo("Arm/Hand");
        assertThat(ref.node()).isEqualTo("Grip");
        assertThat(ref).hasToString("Arm/Hand/Grip");
        assertThat(arm().module("Arm/Hand/Fingers").localName()).isEqualTo("Fingers");
        assertThat(arm().module("Arm/Hand/Fingers").parentName()).isEqualTo("Arm/Hand");
    }

    @Test
    void shouldResolveBareNamesInTheModuleThenOutwardsThenMain() {
        NetworkInfo n = arm();
        assertThat(n.resolve("Arm/Hand/Fingers", "Grip")).isEqualTo(new NodeRef("Arm/Hand", "Grip"));
        assertThat(n.resolve("Arm/Wrist", "Grip")).isEqualTo(new NodeRef("Arm", "Grip"));
        assertThat(n.resolve("Arm/Hand/Fingers", "Clock")).isEqualTo(new NodeRef("main", "Clock"));
        assertThat(n.referenceText("Arm/Wrist", new NodeRef("Arm/Hand", "Grip"))).isEqualTo("Arm/Hand/Grip");
        assertThat(n.referenceText("Arm/Hand/Fingers", new NodeRef("Arm/Hand", "Grip"))).isEqualTo("Grip");
    }

    @Test
    void shouldRefuseModulesInsideMissingParentsOrInsideMain() {
        NetworkInfo n = arm();
        assertThatThrownBy(() -> n.addModule("Leg/Foot", true)).isInstanceOf(EditRefusedException.class)
                .hasMessageContaining("inside module 'Leg'");
        assertThatThrownBy(() -> n.addModule("main/Foot", true)).hasMessageContaining("inside 'main'");
        assertThatThrownBy(() -> n.addModule("Arm//Foot", true)).hasMessageContaining("may not be empty");
    }

    @Test
    void shouldDeleteAModuleWithEverythingInsideIt() {
        NetworkInfo n = arm();
        n.deleteModule("Arm/Hand");
        assertThat(n.modules()).extracting(ModuleInfo::name).containsExactly("main", "Arm", "Arm/Wrist");
    }

    @Test
    void shouldRenameAModuleWithItsChildrenAndTheirConnections() {
        NetworkInfo n = arm();
        n.renameModule("Arm/Hand", "Paw");
        assertThat(n.modules()).extracting(ModuleInfo::name)
                .containsExactly("main", "Arm", "Arm/Paw", "Arm/Paw/Fingers", "Arm/Wrist");
        assertThat(n.connectionsOf(new NodeRef("Arm/Paw", "Grip"))).hasSize(1);
        assertThatThrownBy(() -> n.renameModule("Arm/Paw", "Leg/Paw")).hasMessageContaining("keeps a module where it is");
    }

    @Test
    void shouldLoadLoadAtStartChildrenWithTheirParentAndUnloadTheWholeSubtree() {
        NetworkInfo n = arm();
        assertThat(ModuleTree.atStart(n)).containsExactly("main", "Arm", "Arm/Hand");
        assertThat(ModuleTree.children(n, "Arm")).extracting(ModuleInfo::name).containsExactly("Arm/Hand", "Arm/Wrist");
        Set<String> none = Set.of("main");
        assertThat(ModuleTree.afterLoad(n, none, "Arm")).containsExactlyInAnyOrder("main", "Arm", "Arm/Hand");
        Set<String> all = Set.of("main", "Arm", "Arm/Hand", "Arm/Hand/Fingers", "Arm/Wrist");
        assertThat(ModuleTree.afterUnload(all, "Arm/Hand")).containsExactlyInAnyOrder("main", "Arm", "Arm/Wrist");
        assertThat(ModuleTree.whyNotLoadable(n, none, "Arm/Hand/Fingers")).contains("load 'Arm/Hand' first");
        assertThat(ModuleTree.subtree(n, "Arm/Hand")).isEqualTo(List.of("Arm/Hand", "Arm/Hand/Fingers"));
    }

    @Test
    void shouldLoadANestedChildAtStartOnlyWhenItsParentIs() {
        NetworkInfo n = new NetworkInfo("n");
        n.addModule("Tool", false);
        n.addModule("Tool/Blade", true);
        assertThat(ModuleTree.atStart(n)).containsExactly("main");
        assertThat(ModuleTree.loadedWith(n, "Tool")).containsExactly("Tool", "Tool/Blade");
    }
}
