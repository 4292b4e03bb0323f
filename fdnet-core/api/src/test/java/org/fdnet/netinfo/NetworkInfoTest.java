package org.fdnet.netinfo;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

class NetworkInfoTest {
    private NetworkInfo network;
    private final List<NetworkChange> changes = new ArrayList<>();

    private static final NodeRef SENSOR = new NodeRef("main", "Sensor");
    private static final NodeRef POSTURE = new NodeRef("main", "Posture");
    private static final NodeRef WALK = new NodeRef("Walk", "Walk");
    private static final NodeRef STEP = new NodeRef("Walk", "Step");
    private static final NodeRef BALANCE = new NodeRef("Balance", "Balance");

    /** main: Sensor, Posture (Datas); Walk: Walk (Relation), Step (Data); Balance: Balance (Relation). */
    @BeforeEach
    void buildNetwork() {
        network = new NetworkInfo("test");
        network.addModule("Walk", true);
        network.addModule("Balance", false);
        network.addNode("main", NodeInfo.data("Sensor", "S"));
        network.addNode("main", NodeInfo.data("Posture", "S"));
        network.addNode("Walk", NodeInfo.relation("Walk", "R", Parameter.named("gain", "1")));
        network.addNode("Walk", NodeInfo.data("Step", "S"));
        network.addNode("Balance", NodeInfo.relation("Balance", "R", Parameter.named("gain", "2"), Parameter.named("k", "3")));
        network.addConnection("Walk", ConnectionInfo.reader(SENSOR, WALK));
        network.addConnection("Walk", ConnectionInfo.writer(WALK, STEP));
        network.addConnection("Balance", ConnectionInfo.reader(STEP, BALANCE));
        network.addConnection("Balance", ConnectionInfo.writer(BALANCE, POSTURE));
        network.addConnection("main", ConnectionInfo.reader(POSTURE, WALK));
        network.addListener(changes::add);
    }

    private void assertRefusedAndUntouched(Executable edit, String messagePart) {
        NetworkInfo before = network.copy();
        int told = changes.size();
        assertThatThrownBy(edit::execute).isInstanceOf(EditRefusedException.class).hasMessageContaining(messagePart);
        assertThat(network).isEqualTo(before);
        assertThat(changes).hasSize(told);
    }

    @Test
    void shouldAlwaysHaveMainLoadedAtStart() {
        NetworkInfo empty = new NetworkInfo(null);
        assertThat(empty.main().loadAtStart()).isTrue();
        assertThat(empty.modules()).extracting(ModuleInfo::name).containsExactly("main");
        assertRefusedAndUntouched(() -> network.setLoadAtStart("main", false), "always loaded");
    }

    @Test
    void shouldRefuseDuplicateAndMalformedModuleNames() {
        assertRefusedAndUntouched(() -> network.addModule("Walk", false), "already has a module named 'Walk'");
        // a '/' nests a module: inside a module that exists, or not at all
        assertRefusedAndUntouched(() -> network.addModule("a/b", false), "inside module 'a', which the network does not have");
        assertRefusedAndUntouched(() -> network.addModule("Walk/", false), "may not be empty");
        assertRefusedAndUntouched(() -> network.addModule(" ", false), "may not be empty");
        assertRefusedAndUntouched(() -> network.addModule("tab\there", false), "control characters");
    }

    @Test
    void shouldDeleteModuleWithEveryConnectionTouchingItsNodesAnywhere() {
        network.deleteModule("Walk");
        assertThat(network.module("Walk")).isNull();
        // Balance read Walk/Step: that connection went too; Balance's writer to main stays.
        assertThat(network.module("Balance").connections()).containsExactly(ConnectionInfo.writer(BALANCE, POSTURE));
        assertThat(network.main().connections()).isEmpty();
        assertThat(network.main().nodes()).hasSize(2);
        assertThat(changes).extracting(NetworkChange::kind).containsExactly(NetworkChange.Kind.MODULE_DELETED);
    }

    @Test
    void shouldRefuseDeletingMainOrUnknownModules() {
        assertRefusedAndUntouched(() -> network.deleteModule("main"), "cannot be deleted");
        assertRefusedAndUntouched(() -> network.deleteModule("Nope"), "no module named 'Nope'");
    }

    @Test
    void shouldRenameModuleAndRepointConnectionsEverywhere() {
        network.renameModule("Walk", "Gait");
        NodeRef step = new NodeRef("Gait", "Step");
        assertThat(network.module("Gait").hasNode("Step")).isTrue();
        assertThat(network.module("Balance").connections()).contains(ConnectionInfo.reader(step, BALANCE));
        assertThat(network.modules()).extracting(ModuleInfo::name).containsExactly("main", "Gait", "Balance");
        assertThat(network.connectionsOf(step)).hasSize(2);
        assertRefusedAndUntouched(() -> network.renameModule("Gait", "Balance"), "already has a module named 'Balance'");
    }

    @Test
    void shouldRefuseRenamingMain() {
        assertRefusedAndUntouched(() -> network.renameModule("main", "core"), "cannot be renamed");
    }

    @Test
    void shouldRefuseDuplicateNodeNamesButAllowThemAcrossModules() {
        assertRefusedAndUntouched(() -> network.addNode("Walk", NodeInfo.data("Step", "S")), "already has a node named 'Step'");
        network.addNode("Balance", NodeInfo.data("Step", "S"));
        assertThat(network.node(new NodeRef("Balance", "Step"))).isNotNull();
    }

    @Test
    void shouldDeleteNodeAndAllItsConnectionsInEveryModule() {
        network.deleteNode(WALK);
        assertThat(network.node(WALK)).isNull();
        assertThat(network.connectionsOf(SENSOR)).isEmpty();
        assertThat(network.main().connections()).isEmpty();
        assertThat(network.module("Walk").connections()).isEmpty();
        assertThat(network.module("Balance").connections()).hasSize(2);
    }

    @Test
    void shouldRenameNodeWithConnectionsFollowingAndRefuseClashes() {
        NodeRef renamed = network.renameNode(STEP, "Stride");
        assertThat(network.connectionsOf(renamed)).hasSize(2);
        assertThat(network.connectionsOf(STEP)).isEmpty();
        changes.clear();
        assertRefusedAndUntouched(() -> network.renameNode(renamed, "Walk"), "replace or merge");
    }

    @Test
    void shouldReplaceNodeKeepingOnlyTheReplacementsConnections() {
        network.addNode("main", NodeInfo.data("PostureBeta", "S2"));
        NodeRef beta = new NodeRef("main", "PostureBeta");
        network.addConnection("main", ConnectionInfo.reader(beta, BALANCE));
        NodeRef result = network.replaceNode(POSTURE, beta);
        assertThat(result).isEqualTo(POSTURE);
        assertThat(network.node(POSTURE).className()).isEqualTo("S2");
        assertThat(network.node(beta)).isNull();
        assertThat(network.connectionsOf(POSTURE)).extracting(LinkedConnection::connection)
                .containsExactly(ConnectionInfo.reader(POSTURE, BALANCE));
        // the replaced node kept its place in the declaration order
        assertThat(network.main().nodes()).extracting(NodeInfo::name).containsExactly("Sensor", "Posture");
    }

    @Test
    void shouldRefuseReplacingAcrossModulesOrWithItself() {
        assertRefusedAndUntouched(() -> network.replaceNode(POSTURE, STEP), "different modules");
        assertRefusedAndUntouched(() -> network.replaceNode(POSTURE, POSTURE), "cannot replace itself");
    }

    @Test
    void shouldMergeNodesRedirectingConnectionsAndCollapsingDuplicates() {
        network.addNode("Balance", NodeInfo.relation("Balance2", "R", Parameter.named("k", "9"), Parameter.named("z", "1")));
        NodeRef second = new NodeRef("Balance", "Balance2");
        network.addConnection("Balance", ConnectionInfo.reader(STEP, second));     // duplicates Balance's reader once merged
        network.addConnection("Balance", ConnectionInfo.reader(SENSOR, second));
        network.mergeNodes(BALANCE, second, MergePolicy.BOTH);
        assertThat(network.node(second)).isNull();
        assertThat(network.node(BALANCE).parameters()).extracting(Parameter::toString).containsExactly("gain=2", "k=3", "z=1");
        assertThat(network.connectionsOf(BALANCE)).extracting(LinkedConnection::connection).containsExactlyInAnyOrder(
                ConnectionInfo.reader(STEP, BALANCE), ConnectionInfo.writer(BALANCE, POSTURE), ConnectionInfo.reader(SENSOR, BALANCE));
    }

    @Test
    void shouldMergeParametersByPolicy() {
        network.addNode("Balance", NodeInfo.relation("Other", "R", Parameter.named("x", "5")));
        NetworkInfo first = network.copy();
        NetworkInfo secondOnly = network.copy();
        NodeRef other = new NodeRef("Balance", "Other");
        first.mergeNodes(BALANCE, other, MergePolicy.FIRST);
        secondOnly.mergeNodes(BALANCE, other, MergePolicy.SECOND);
        assertThat(first.node(BALANCE).parameters()).extracting(Parameter::name).containsExactly("gain", "k");
        assertThat(secondOnly.node(BALANCE).parameters()).extracting(Parameter::name).containsExactly("x");
    }

    @Test
    void shouldRefuseMergingDataWithRelation() {
        assertRefusedAndUntouched(() -> network.mergeNodes(STEP, WALK, MergePolicy.BOTH), "cannot merge");
        assertRefusedAndUntouched(() -> network.mergeNodes(STEP, STEP, MergePolicy.BOTH), "itself");
    }

    @Test
    void shouldRefuseDanglingMismatchedAndDuplicateConnections() {
        assertRefusedAndUntouched(() -> network.addConnection("main", ConnectionInfo.reader(new NodeRef("main", "Ghost"), WALK)),
                "has no node 'Ghost'");
        assertRefusedAndUntouched(() -> network.addConnection("main", ConnectionInfo.reader(new NodeRef("Nowhere", "X"), WALK)),
                "no module 'Nowhere'");
        assertRefusedAndUntouched(() -> network.addConnection("main", ConnectionInfo.reader(SENSOR, POSTURE)),
                "must join one Data and one Relation");
        assertRefusedAndUntouched(() -> network.addConnection("Balance", ConnectionInfo.reader(SENSOR, WALK)), "duplicate");
    }

    @Test
    void shouldFindAllConnectionsOfANodeAcrossModules() {
        assertThat(network.connectionsOf(WALK)).extracting(LinkedConnection::module).containsExactlyInAnyOrder("Walk", "Walk", "main");
    }

    @Test
    void shouldComputeDescendantsAndAncestorsTransitivelyThroughFeedback() {
        // Sensor → Walk → Step → Balance → Posture → Walk (feedback loop through Posture)
        assertThat(network.descendants(SENSOR)).containsExactly(WALK, STEP, BALANCE, POSTURE);
        assertThat(network.descendants(STEP)).containsExactlyInAnyOrder(BALANCE, POSTURE, WALK, STEP);
        assertThat(network.ancestors(STEP)).containsExactlyInAnyOrder(WALK, SENSOR, POSTURE, BALANCE, STEP);
        assertThat(network.ancestors(SENSOR)).isEmpty();
        assertRefusedAndUntouched(() -> network.descendants(new NodeRef("main", "Ghost")), "no node named 'Ghost'");
    }

    @Test
    void shouldCountPerModuleAndInTotal() {
        assertThat(network.counts("main")).isEqualTo(new ModuleCounts(2, 0, 1, 0));
        assertThat(network.counts("Walk")).isEqualTo(new ModuleCounts(1, 1, 1, 1));
        assertThat(network.totalCounts()).isEqualTo(new ModuleCounts(3, 2, 3, 2));
    }

    @Test
    void shouldResolveOwnModuleFirstThenMain() {
        network.addNode("Walk", NodeInfo.data("Sensor", "S"));
        assertThat(network.resolve("Walk", "Sensor")).isEqualTo(new NodeRef("Walk", "Sensor"));
        assertThat(network.resolve("Balance", "Sensor")).isEqualTo(SENSOR);
        assertThat(network.resolve("Balance", "main/Sensor")).isEqualTo(SENSOR);
        assertThat(network.resolve("Balance", "Step")).isNull();
        assertThat(network.referenceText("Walk", SENSOR)).isEqualTo("main/Sensor");
        assertThat(network.referenceText("Balance", SENSOR)).isEqualTo("Sensor");
        assertThat(network.referenceText("Balance", STEP)).isEqualTo("Walk/Step");
    }

    @Test
    void shouldTellListenersOfEachCompletedEdit() {
        network.addModule("Arm", false);
        network.setLoadAtStart("Arm", true);
        network.addNode("Arm", NodeInfo.data("Elbow", "S"));
        network.setParameters(new NodeRef("Arm", "Elbow"), List.of(Parameter.of("1")));
        network.setName("renamed");
        assertThat(changes).extracting(NetworkChange::kind).containsExactly(NetworkChange.Kind.MODULE_ADDED,
                NetworkChange.Kind.MODULE_LOAD_AT_START_CHANGED, NetworkChange.Kind.NODE_ADDED,
                NetworkChange.Kind.NODE_CHANGED, NetworkChange.Kind.NETWORK_RENAMED);
        assertThat(network.module("Arm").loadAtStart()).isTrue();
        assertThat(network.node(new NodeRef("Arm", "Elbow")).parameters()).containsExactly(Parameter.of("1"));
    }

    @Test
    void shouldRefuseTurningAConnectedDataIntoARelation() {
        NodeInfo asRelation = new NodeInfo(NodeKind.RELATION, "Step", "localhost", "", "R", List.of());
        assertRefusedAndUntouched(() -> network.updateNode(STEP, asRelation), "is connected");
    }

    @Test
    void shouldRejectInvalidTypedParameterValues() {
        assertThatThrownBy(() -> new Parameter("period", ParameterType.LONG, "12ms"))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("not a whole number");
        assertThat(ParameterType.DOUBLES.parse("1, 2 3")).isEqualTo(new double[] {1, 2, 3});
        assertThat(ParameterType.BOOLEAN.parse("yes")).isEqualTo(Boolean.TRUE);
    }
}
