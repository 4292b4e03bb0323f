package org.fdnet.hi.edit;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.layout.NodeLayout;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.MergePolicy;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.xml.LayoutRepository;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Every edit, its undo and redo, and refusals, on the real roq-motion network (no display needed). */
class UndoableNetworkEditorTest {
    private static final Path ROQ = Path.of("..", "networks", "roq-motion.fdn");
    private static final NodeRef JUDGE = new NodeRef("Integration", "judge");
    private static final NodeRef JUDGMENT = new NodeRef("Integration", "judgment");
    private static final NodeRef PRESENT = new NodeRef("main", "A present posture");
    private static final NodeRef PHYSICAL = new NodeRef("main", "Physical information");
    private static final NodeRef KEEP = new NodeRef("Balance", "keep a balance");
    private static final NodeRef WALK = new NodeRef("Walk", "walk");

    private NetworkInfo network;
    private NetworkLayout layout;
    private UndoableNetworkEditor editor;
    private final List<String> refusals = new ArrayList<>();
    private int historyChanges;

    @BeforeEach
    void open() throws Exception {
        network = NetworkRepository.load(ROQ);
        layout = LayoutRepository.load(LayoutRepository.sideFileOf(ROQ));
        editor = new UndoableNetworkEditor(network, layout);
        editor.addEditorListener(new EditorListener() {
            @Override
            public void historyChanged() {
                historyChanges++;
            }

            @Override
            public void refused(String reason) {
                refusals.add(reason);
            }
        });
    }

    /** Applies the edit, then checks that undo gives back the very network (order included) and redo the edited one. */
    private void assertUndoable(Function<UndoableNetworkEditor, EditResult> edit) {
        NetworkInfo before = network.copy();
        byte[] beforeBytes = NetworkRepository.toBytes(network, null);
        EditResult result = edit.apply(editor);
        assertThat(result.accepted()).as(result.reason()).isTrue();
        assertThat(network).isNotEqualTo(before);
        assertThat(editor.dirty()).isTrue();
        NetworkInfo after = network.copy();

        assertThat(editor.undo().accepted()).isTrue();
        assertThat(network).isEqualTo(before);
        assertThat(NetworkRepository.toBytes(network, null)).isEqualTo(beforeBytes);
        assertThat(editor.dirty()).isFalse();

        assertThat(editor.redo().accepted()).isTrue();
        assertThat(network).isEqualTo(after);
        assertThat(editor.dirty()).isTrue();
        assertThat(editor.undo().accepted()).isTrue();
        assertThat(network).isEqualTo(before);
        assertThat(refusals).isEmpty();
    }

    @Test
    void shouldUndoAndRedoAddingAModule() {
        assertUndoable(e -> e.addModule("Vision", false));
    }

    @Test
    void shouldGiveBackADeletedModuleWithItsNodesAndEveryConnectionToIt() {
        assertUndoable(e -> e.deleteModule("Walk"));
    }

    @Test
    void shouldUndoRenamingAModuleAndCarryItsLayout() {
        assertUndoable(e -> e.renameModule("Walk", "Gait"));
        editor.redo();
        assertThat(layout.node(new NodeRef("Gait", "walk"))).isEqualTo(layout.node(WALK));
    }

    @Test
    void shouldUndoRenamingTheNetworkAndRefuseAnEmptyName() {
        assertUndoable(e -> e.renameNetwork("ロボット motion"));
        editor.redo();
        assertThat(network.name()).isEqualTo("ロボット motion");
        assertThat(new String(NetworkRepository.toBytes(network, null), java.nio.charset.StandardCharsets.UTF_8))
                .contains("<cnet name=\"ロボット motion\"");
        assertThat(editor.renameNetwork(" ").accepted()).isFalse();
        assertThat(refusals).containsExactly("network name may not be empty");
        assertThat(network.name()).isEqualTo("ロボット motion");
    }

    @Test
    void shouldUndoChangingLoadAtStart() {
        assertUndoable(e -> e.setLoadAtStart("Walk", false));
    }

    @Test
    void shouldUndoAddingANode() {
        assertUndoable(e -> e.addNode("Balance", NodeInfo.data("tilt", "org.fdnet.runtime.library.DoubleData")));
    }

    @Test
    void shouldUndoUpdatingANode() {
        assertUndoable(e -> e.updateNode(JUDGE, network.node(JUDGE).withHost("robot-2")));
    }

    @Test
    void shouldUndoAnUpdateThatRenamesTheNode() {
        assertUndoable(e -> e.updateNode(JUDGE, network.node(JUDGE).withName("arbiter").withHost("robot-2")));
    }

    @Test
    void shouldUndoSettingParameters() {
        assertUndoable(e -> e.setParameters(JUDGE, List.of(Parameter.named("expression", "in1"))));
    }

    @Test
    void shouldGiveBackADeletedNodeAtItsPlaceWithItsConnections() {
        assertUndoable(e -> e.deleteNode(PRESENT));
        assertThat(network.connectionsOf(PRESENT)).hasSize(NetworkInfoCounts.connectionsOf(PRESENT));
    }

    @Test
    void shouldUndoRenamingANodeAndKeepItsPlaceOnScreen() {
        NodeLayout place = layout.node(JUDGE);
        assertUndoable(e -> e.renameNode(JUDGE, "arbiter"));
        editor.redo();
        assertThat(layout.node(new NodeRef("Integration", "arbiter"))).isEqualTo(place);
    }

    @Test
    void shouldUndoReplacingANode() {
        assertUndoable(e -> e.replaceNode(JUDGE, new NodeRef("Integration", "integrate")));
    }

    @Test
    void shouldUndoMergingTwoNodesWithEachPolicy() {
        for (MergePolicy policy : MergePolicy.values()) {
            assertUndoable(e -> e.mergeNodes(PHYSICAL, JUDGMENT, policy));
        }
    }

    @Test
    void shouldUndoAddingAndDeletingAConnection() {
        ConnectionInfo reader = ConnectionInfo.reader(JUDGMENT, KEEP);
        assertUndoable(e -> e.addConnection("Balance", reader));
        ConnectionInfo first = network.module("main").connections().get(0);
        assertUndoable(e -> e.deleteConnection("main", first));
    }

    @Test
    void shouldUndoChangingAConnectionInPlace() {
        ConnectionInfo first = network.module("main").connections().get(1);
        ConnectionInfo named = new ConnectionInfo(first.kind(), "watch posture", first.data(), first.relation(),
                false, false, false);
        assertUndoable(e -> e.updateConnection("main", first, named));
        editor.redo();
        assertThat(network.module("main").connections().get(1)).isEqualTo(named);
    }

    @Test
    void shouldUndoSeveralEditsInReverseOrder() {
        NetworkInfo before = network.copy();
        editor.deleteNode(PRESENT);
        editor.renameModule("Walk", "Gait");
        editor.mergeNodes(new NodeRef("Gait", "walk"), KEEP, MergePolicy.BOTH);
        editor.addModule("Vision", true);
        while (editor.canUndo()) {
            assertThat(editor.undo().accepted()).isTrue();
        }
        assertThat(network).isEqualTo(before);
        assertThat(editor.redoLabel()).isEqualTo("Delete node main/A present posture");
    }

    @Test
    void shouldLeaveModelLayoutAndHistoryUnchangedWhenAnEditIsRefused() throws Exception {
        NetworkInfo before = network.copy();
        NetworkLayout layoutBefore = LayoutRepository.load(LayoutRepository.sideFileOf(ROQ));
        List<EditResult> results = List.of(
                editor.addModule("Walk", true),
                editor.deleteModule("main"),
                editor.renameModule("Walk", "Balance"),
                editor.setLoadAtStart("main", false),
                editor.addNode("main", NodeInfo.data("inclinometer", "X")),
                editor.updateNode(JUDGE, NodeInfo.data("judge", "X")),
                editor.updateNode(JUDGE, network.node(JUDGE).withName("integrate")),
                editor.deleteNode(new NodeRef("main", "nobody")),
                editor.renameNode(JUDGE, "integrate"),
                editor.replaceNode(JUDGE, JUDGE),
                editor.mergeNodes(PHYSICAL, KEEP, MergePolicy.FIRST),
                editor.addConnection("main", ConnectionInfo.reader(PHYSICAL, new NodeRef("main", "posture monitor"))),
                editor.deleteConnection("main", ConnectionInfo.reader(JUDGMENT, KEEP)),
                editor.updateConnection("main", network.module("main").connections().get(0),
                        ConnectionInfo.reader(PHYSICAL, PRESENT)));
        assertThat(results).allSatisfy(r -> {
            assertThat(r.accepted()).isFalse();
            assertThat(r.reason()).isNotBlank();
        });
        assertThat(refusals).hasSize(results.size());
        assertThat(network).isEqualTo(before);
        assertThat(layout).isEqualTo(layoutBefore);
        assertThat(editor.canUndo()).isFalse();
        assertThat(editor.dirty()).isFalse();
        assertThat(historyChanges).isZero();
    }

    @Test
    void shouldBeCleanAgainAfterSaveAndDirtyAfterUndoingPastTheSave() {
        editor.deleteNode(PRESENT);
        editor.markSaved();
        assertThat(editor.dirty()).isFalse();
        editor.undo();
        assertThat(editor.dirty()).isTrue();
        editor.redo();
        assertThat(editor.dirty()).isFalse();
    }

    /** Counts taken from the file itself, so the test states what the network holds. */
    private static final class NetworkInfoCounts {
        static int connectionsOf(NodeRef ref) {
            try {
                return NetworkRepository.load(ROQ).connectionsOf(ref).size();
            } catch (Exception e) {
                throw new AssertionError(e);
            }
        }
    }

    // ---------------------------------------------------------------- live mode: the gate decides first

    /** A gate that records what it was asked and answers as told (the running network's part, in one line). */
    private static final class RecordingGate implements EditGate {
        final List<String> asked = new ArrayList<>();
        String refuseWith;

        @Override
        public org.fdnet.runtime.ChangeOutcome admit(String label, NetworkInfo before, NetworkInfo after) {
            asked.add(label + ": " + org.fdnet.control.NetworkDiff.between(before, after).entries());
            return refuseWith == null ? org.fdnet.runtime.ChangeOutcome.executed(label)
                    : org.fdnet.runtime.ChangeOutcome.failed(label, refuseWith);
        }
    }

    @Test
    void shouldAskTheGateWithTheEditedNetworkBeforeChangingAnything() {
        RecordingGate gate = new RecordingGate();
        editor.setGate(gate);

        EditResult result = editor.deleteNode(JUDGE);

        assertThat(result.accepted()).isTrue();
        assertThat(network.node(JUDGE)).isNull();
        assertThat(gate.asked).hasSize(1);
        assertThat(gate.asked.get(0)).startsWith("Delete node Integration/judge: ").contains("- node Integration/judge");
    }

    @Test
    void shouldChangeNothingAndSayWhyWhenTheGateRefuses() {
        RecordingGate gate = new RecordingGate();
        gate.refuseWith = "class not found";
        editor.setGate(gate);
        NetworkInfo before = network.copy();

        EditResult result = editor.renameNode(JUDGE, "arbiter");

        assertThat(result.accepted()).isFalse();
        assertThat(result.reason()).isEqualTo("the running network refused it: class not found");
        assertThat(refusals).containsExactly(result.reason());
        assertThat(network).isEqualTo(before);
        assertThat(editor.canUndo()).isFalse();
    }

    @Test
    void shouldSendUndoAndRedoThroughTheGateAndKeepTheStepWhenRefused() {
        RecordingGate gate = new RecordingGate();
        editor.setGate(gate);
        editor.deleteNode(JUDGE);
        NetworkInfo deleted = network.copy();

        gate.refuseWith = "the network is busy";
        assertThat(editor.undo().accepted()).isFalse();
        assertThat(network).isEqualTo(deleted);
        assertThat(editor.canUndo()).as("the step stays to be tried again").isTrue();

        gate.refuseWith = null;
        assertThat(editor.undo().accepted()).isTrue();
        assertThat(network.node(JUDGE)).isNotNull();
        assertThat(editor.redo().accepted()).isTrue();
        assertThat(gate.asked).extracting(a -> a.substring(0, a.indexOf(':')))
                .containsExactly("Delete node Integration/judge", "Undo Delete node Integration/judge",
                        "Undo Delete node Integration/judge", "Redo Delete node Integration/judge");
    }

    @Test
    void shouldAdoptAChangeFromElsewhereWithoutTheGateTheHistoryOrTheDirtyMark() {
        RecordingGate gate = new RecordingGate();
        editor.setGate(gate);
        NetworkInfo running = network.copy();
        running.addNode("main", NodeInfo.data("built by a Servant", "org.fdnet.runtime.library.DoubleData"));

        editor.adopt(org.fdnet.control.NetworkDiff.between(network, running).asEdit());

        assertThat(network).isEqualTo(running);
        assertThat(gate.asked).isEmpty();
        assertThat(editor.canUndo()).isFalse();
        assertThat(editor.dirty()).isFalse();
    }
}
