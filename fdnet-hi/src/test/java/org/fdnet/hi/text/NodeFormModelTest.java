package org.fdnet.hi.text;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;

import org.fdnet.hi.speedy.SpeedyDesign;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.testing.NodeJars;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class NodeFormModelTest {
    private final NetworkInfo network = SampleNetwork.create();
    private final PlainNetworkEditor editor = new PlainNetworkEditor(network);
    private final SpeedyDesign speedy = new SpeedyDesign();
    private final NodeFormModel form = new NodeFormModel(editor, "main", speedy);

    private void type(String name) {
        for (int i = 1; i <= name.length(); i++) {
            form.typeName(name.substring(0, i)); // keystroke by keystroke, as a document listener reports it
        }
    }

    @Test
    void shouldLoadAnExistingNodeWhenItsNameIsTypedAndTurnSaveIntoUpdate() {
        assertThat(form.saveLabel()).isEqualTo("Save");
        type("Speed");

        assertThat(form.loaded()).isEqualTo(SampleNetwork.SPEED);
        assertThat(form.saveLabel()).isEqualTo("Update");
        assertThat(form.canDelete()).isTrue();
        assertThat(form.host()).isEqualTo("roq");
        assertThat(form.path()).isEqualTo("/opt/nodes");
        assertThat(form.className()).isEqualTo("fdnet.SpeedData");
        assertThat(form.parameters()).containsExactly(new Parameter("gain", ParameterType.LONG, "3"), Parameter.of("fast"));
    }

    @Test
    void shouldKeepWhatTheUserTypedWhenTheNameNamesNoNode() {
        form.typeClass("my.Class");
        form.typeHost("alpha");
        type("Spee");

        assertThat(form.loaded()).isNull();
        assertThat(form.saveLabel()).isEqualTo("Save");
        assertThat(form.className()).isEqualTo("my.Class");
        assertThat(form.host()).isEqualTo("alpha");
    }

    @Test
    void shouldAddANewNodeWithTypedParametersAndThenOfferUpdate() {
        type("Gain");
        form.chooseKind(NodeKind.DATA);
        form.typeClass("fdnet.Gain");
        assertThat(form.addParameter("k", ParameterType.DOUBLE, "0.5")).isNull();
        assertThat(form.addParameter("", null, "plain")).isNull();

        assertThat(form.save().accepted()).isTrue();

        NodeInfo added = network.node(new NodeRef("main", "Gain"));
        assertThat(added.className()).isEqualTo("fdnet.Gain");
        assertThat(added.parameters()).containsExactly(new Parameter("k", ParameterType.DOUBLE, "0.5"), Parameter.of("plain"));
        assertThat(form.saveLabel()).as("the network changed: the typed name now exists").isEqualTo("Update");
    }

    @Test
    void shouldRefuseAParameterThatDoesNotMatchItsTypeAndKeepTheOthers() {
        type("Speed");
        String why = form.addParameter("count", ParameterType.LONG, "three");

        assertThat(why).contains("parameter 3").contains("'three' is not a whole number");
        assertThat(form.parameters()).hasSize(2);
    }

    @Test
    void shouldUpdateTheLoadedNodeKeepingItsConnections() {
        type("Speed");
        form.typeHost("beta");
        form.editParameter(0, "gain", ParameterType.LONG, "7");
        form.deleteParameter(1);

        assertThat(form.save().accepted()).isTrue();

        NodeInfo speed = network.node(SampleNetwork.SPEED);
        assertThat(speed.host()).isEqualTo("beta");
        assertThat(speed.parameters()).containsExactly(new Parameter("gain", ParameterType.LONG, "7"));
        assertThat(network.connectionsOf(SampleNetwork.SPEED)).hasSize(2);
    }

    @Test
    void shouldDeleteTheLoadedNodeWithEveryConnectionNamingItInAnyModule() {
        type("Speed");

        assertThat(form.delete().accepted()).isTrue();

        assertThat(network.node(SampleNetwork.SPEED)).isNull();
        assertThat(network.main().connections()).hasSize(1);
        assertThat(network.module("Arm").connections()).hasSize(1);
        assertThat(form.loaded()).isNull();
        assertThat(form.saveLabel()).isEqualTo("Save");
    }

    @Test
    void shouldReloadTheNodeWhenItIsChangedElsewhere() {
        type("Control");
        network.updateNode(SampleNetwork.CONTROL, network.node(SampleNetwork.CONTROL).withHost("gamma"));

        assertThat(form.host()).isEqualTo("gamma");
    }

    @Test
    void shouldSayWhySaveCannotRun() {
        assertThat(form.whyNotSave()).isEqualTo("type the node's name");
        type("New");
        assertThat(form.whyNotSave()).isEqualTo("type the node's class");
        form.typeClass("x.New");
        assertThat(form.whyNotSave()).isNull();
        assertThat(form.save().accepted()).isTrue();
        assertThat(network.main().nodes()).extracting(NodeInfo::name).containsExactly("Speed", "Control", "Command", "New");
        assertThat(List.of(form.loaded())).containsExactly(new NodeRef("main", "New"));
    }

    @Test
    void shouldUpdateEachDependentWidgetExactlyOncePerKeystrokeAndPerNetworkChange() {
        List<String> log = new java.util.ArrayList<>();
        speedy.register("view:details", () -> log.add("details"), form.details());
        speedy.register("view:actions", () -> log.add("actions"), form.actions());
        speedy.register("view:both", () -> log.add("both"), form.details(), form.actions());

        form.typeName("S");
        assertThat(log).containsExactly("details", "actions", "both");

        log.clear();
        network.addNode("Arm", NodeInfo.data("Wrist", "fdnet.Wrist"));
        assertThat(log).containsExactly("details", "actions", "both");

        log.clear();
        form.typeHost("h");
        assertThat(log).as("a detail typed: the details widgets are the source's children, the name is not")
                .containsExactly("details", "actions", "both");
    }

    @Test
    void shouldFollowItsModuleWhenItIsRenamedElsewhere() {
        NodeFormModel arm = new NodeFormModel(editor, "Arm", speedy);
        network.renameModule("Arm", "LeftArm");
        arm.typeName("Angle");

        assertThat(arm.module()).isEqualTo("LeftArm");
        assertThat(arm.loaded()).isEqualTo(new NodeRef("LeftArm", "Angle"));
    }

    @Test
    void shouldListTheParametersTheTypedClassDeclaresWithTheirDescriptions() {
        type("Switch");
        form.chooseKind(NodeKind.RELATION);
        form.typeClass("org.fdnet.runtime.library.Threshold");
        assertThat(form.declaredProblem()).isNull();
        assertThat(form.declaredParameters()).extracting(ParameterSpec::name)
                .startsWith("high", "low", "absolute").contains("period");
        assertThat(form.declaredParameters().get(0).description())
                .isEqualTo("the output becomes true when the input rises above it");
    }

    @Test
    void shouldOfferADeclaredParameterWithItsTypeAndDefaultValue() {
        form.chooseKind(NodeKind.RELATION);
        form.typeClass("org.fdnet.runtime.library.Threshold");
        assertThat(form.offered("absolute")).isEqualTo(new NodeFormModel.Offer("absolute", ParameterType.BOOLEAN, "false"));
        assertThat(form.offered("high")).isEqualTo(new NodeFormModel.Offer("high", ParameterType.DOUBLE, ""));
        assertThat(form.offered("triggers")).isEqualTo(new NodeFormModel.Offer("triggers", null, ""));
        assertThat(form.offered("nonsense")).isNull();
    }

    @Test
    void shouldSayWhyTheParametersOfAClassItCannotFindAreNotListed() {
        form.chooseKind(NodeKind.RELATION);
        form.typeClass("org.fdnet.runtime.library.NoSuchRelation");
        assertThat(form.declaredParameters()).isEmpty();
        assertThat(form.declaredProblem()).contains("class 'org.fdnet.runtime.library.NoSuchRelation'")
                .contains("no such built-in class");
    }

    @Test
    void shouldOfferTheClassesOfTheKindChosenThatTheNetworksPathsHold(@TempDir Path dir) throws Exception {
        Path classes = NodeJars.compileEmit(dir.resolve("classes"), "1");
        NodeJars.compile(classes, "Level", "public class Level extends org.fdnet.runtime.library.DoubleData {}\n");
        NodeJars.jar(classes, dir.resolve("lib/nodes.jar"));
        NetworkInfo withJar = new NetworkInfo("jarred");
        withJar.addNode("main", new NodeInfo(NodeKind.RELATION, "Source", "localhost", "lib/nodes.jar", "plugin.Emit",
                List.of()));
        NodeFormModel jarForm = new NodeFormModel(new PlainNetworkEditor(withJar, dir.resolve("jarred.fdn")), "main",
                new SpeedyDesign());
        try {
            jarForm.chooseKind(NodeKind.DATA);
            assertThat(jarForm.classChoices()).containsExactly(new NodeClasses.Choice("plugin.Level", "lib/nodes.jar"));
            jarForm.chooseKind(NodeKind.RELATION);
            assertThat(jarForm.classChoices()).containsExactly(new NodeClasses.Choice("plugin.Emit", "lib/nodes.jar"));
            jarForm.chooseClass(jarForm.classChoices().get(0));
            assertThat(jarForm.path()).isEqualTo("lib/nodes.jar");
            assertThat(jarForm.className()).isEqualTo("plugin.Emit");
            assertThat(jarForm.declaredParameters()).extracting(ParameterSpec::name)
                    .containsExactly("period", "onInput", "triggers");
            jarForm.typePath("../outside");
            assertThat(jarForm.classChoices()).hasSize(1);
            assertThat(jarForm.classScanProblem()).contains("path '../outside'");
            jarForm.typePath("lib/nodes.jar");
            assertThat(jarForm.classChoices()).hasSize(1);
            assertThat(jarForm.classScanProblem()).as("a path typed on from a bad one").isNull();
        } finally {
            jarForm.detach();
        }
    }
}
