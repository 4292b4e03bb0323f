package org.fdnet.hi.live;

import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.hi.live.LiveTestNetwork.LIB;
import static org.fdnet.hi.live.LiveTestNetwork.edt;
import static org.fdnet.hi.live.LiveTestNetwork.eventually;
import static org.fdnet.hi.live.LiveTestNetwork.ref;

import java.awt.geom.Rectangle2D;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import org.fdnet.control.LiveNetwork;
import org.fdnet.control.NetworkDiff;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.edit.UndoableNetworkEditor;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.ChangeOutcome;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The live session against a real network running in this JVM (no window: the editor, its scene and the
 * session are the Swing-thread models the window shows).
 */
@Timeout(60)
class LiveSessionTest {
    private InProcessRun run;
    private UndoableNetworkEditor editor;
    private GraphScene scene;
    private final Heard heard = new Heard();
    private LiveSession session;

    /** What the window would have been told. */
    static final class Heard implements LiveSessionListener {
        final List<String> infos = new CopyOnWriteArrayList<>();
        final List<String> errors = new CopyOnWriteArrayList<>();
        volatile Set<String> loaded = Set.of();
        volatile Set<String> held = Set.of();
        volatile String ended;
        volatile boolean lost;

        @Override
        public void info(String message) {
            infos.add(message);
        }

        @Override
        public void error(String message) {
            errors.add(message);
        }

        @Override
        public void modulesChanged(Set<String> loaded, Set<String> held) {
            this.loaded = loaded;
            this.held = held;
        }

        @Override
        public void ended(boolean lost, String reason) {
            this.lost = lost;
            this.ended = reason;
        }
    }

    @BeforeEach
    void attach() throws Exception {
        run = LiveTestNetwork.start();
        session = edt(() -> {
            editor = new UndoableNetworkEditor(LiveTestNetwork.definition(), new NetworkLayout());
            scene = new GraphScene(editor);
            return LiveSession.attach(run.live(), editor, scene, heard, false);
        });
    }

    @AfterEach
    void stop() throws Exception {
        edt(() -> {
            session.close();
            return null;
        });
        run.close();
    }

    private LiveNetwork network() {
        return run.live();
    }

    @Test
    void shouldShowAnEditOnlyOnceTheRunningNetworkExecutedItAndSendItsUndoToo() throws Exception {
        EditResult result = edt(() -> editor.setParameters(ref("Gain"), List.of(Parameter.named("expression", "3 * in0"))));

        assertThat(result.accepted()).as(String.valueOf(result.reason())).isTrue();
        assertThat(network().snapshot().node(ref("Gain")).parameter("expression")).isEqualTo("3 * in0");
        assertThat(edt(() -> editor.network().node(ref("Gain")).parameter("expression"))).isEqualTo("3 * in0");

        assertThat(edt(() -> editor.undo()).accepted()).isTrue();
        assertThat(network().snapshot().node(ref("Gain")).parameter("expression")).isEqualTo("2 * in0");
        assertThat(edt(() -> editor.network().node(ref("Gain")).parameter("expression"))).isEqualTo("2 * in0");
    }

    @Test
    void shouldLeaveTheViewUntouchedAndSayWhyWhenTheRunningNetworkRefusesAnEdit() throws Exception {
        NetworkInfo before = edt(() -> editor.network().copy());
        List<String> refusals = new CopyOnWriteArrayList<>();
        edt(() -> {
            editor.addEditorListener(new org.fdnet.hi.edit.EditorListener() {
                @Override
                public void historyChanged() {
                }

                @Override
                public void refused(String reason) {
                    refusals.add(reason);
                }
            });
            return null;
        });

        EditResult result = edt(() -> editor.addNode("main", NodeInfo.relation("Broken", "org.fdnet.NoSuchRelation")));

        assertThat(result.accepted()).isFalse();
        assertThat(result.reason()).contains("the running network refused it", "org.fdnet.NoSuchRelation");
        assertThat(refusals).containsExactly(result.reason());
        assertThat(edt(() -> editor.network().copy())).isEqualTo(before);
        assertThat(edt(editor::canUndo)).isFalse();
        assertThat(network().snapshot().node(ref("Broken"))).isNull();
    }

    @Test
    void shouldShowWhatTheNetworkBuiltByItselfAndKeepThePlacesOfTheOtherNodes() throws Exception {
        Rectangle2D gainBefore = edt(() -> scene.bounds(ref("Gain")));

        // another tool plugs in a sensor; the Organizer (AutoFilter) then builds a filter for it by itself
        NetworkInfo base = network().snapshot();
        NetworkInfo edited = base.copy();
        edited.addNode("main", NodeInfo.data("Wheel", LIB + "DoubleSensor"));
        assertThat(network().apply("plug a wheel sensor", base, edited).executed()).isTrue();

        assertThat(eventually(() -> editor.network().node(ref("Wheel filter")) != null
                && editor.network().node(ref("Wheel filtered")) != null))
                .as("the filter the network built shows in the editor").isTrue();
        assertThat(edt(() -> editor.network().connectionsOf(ref("Wheel filter")))).hasSize(2);
        assertThat(edt(() -> scene.bounds(ref("Wheel filter")))).as("the new node has a place").isNotNull();
        assertThat(edt(() -> scene.bounds(ref("Gain")))).isEqualTo(gainBefore);
        assertThat(edt(editor::canUndo)).as("the network's own change is not the user's to undo").isFalse();
        assertThat(heard.infos).anyMatch(m -> m.contains("+ node main/Wheel filter"));
    }

    @Test
    void shouldUnloadAndReloadAModuleAndShowWhichModulesRun() throws Exception {
        assertThat(eventually(() -> heard.loaded.contains("Wave") && scene.liveValue(ref("Wave/signal")) != null)).isTrue();

        assertThat(edt(() -> session.unload("Wave")).executed()).isTrue();
        assertThat(eventually(() -> !heard.loaded.contains("Wave"))).as("Wave shown as not loaded").isTrue();
        assertThat(network().loadedModules()).doesNotContain("Wave");
        assertThat(eventually(() -> scene.liveValue(ref("Wave/signal")) == null)).as("no value drawn on an unloaded Data").isTrue();

        assertThat(edt(() -> session.load("Wave")).executed()).isTrue();
        assertThat(edt(() -> session.hold("Wave")).executed()).isTrue();
        assertThat(eventually(() -> heard.loaded.contains("Wave") && heard.held.contains("Wave"))).isTrue();
        assertThat(edt(() -> session.resume("Wave")).executed()).isTrue();
        assertThat(eventually(() -> heard.held.isEmpty())).isTrue();
        assertThat(edt(() -> session.unload("NoSuchModule")).executed()).isFalse();
        assertThat(heard.errors).anyMatch(m -> m.contains("NoSuchModule"));
    }

    @Test
    void shouldDrawTheLatestValuesOnTheNodesAndSendAValueToAData() throws Exception {
        assertThat(eventually(() -> scene.liveValue(ref("Wave/signal")) != null)).as("Wave/signal's value drawn").isTrue();

        ChangeOutcome sent = edt(() -> session.send(ref("Out"), "42"));
        assertThat(sent.executed()).as(sent.toString()).isTrue();
        ChangeOutcome wrong = edt(() -> session.send(ref("Out"), "forty-two"));
        assertThat(wrong.executed()).isFalse();
        assertThat(heard.errors).anyMatch(m -> m.contains("main/Out"));
    }

    @Test
    void shouldDeployPendingChangesTogetherOrNotAtAll() throws Exception {
        edt(() -> {
            session.startCollecting();
            editor.setParameters(ref("Gain"), List.of(Parameter.named("expression", "3 * in0")));
            editor.addNode("main", NodeInfo.data("Extra", LIB + "DoubleData"));
            return null;
        });
        assertThat(network().snapshot().node(ref("Extra"))).as("collected, not sent").isNull();
        assertThat(edt(() -> session.pending().entries()).stream().map(NetworkDiff.Entry::text))
                .containsExactlyInAnyOrder("+ node main/Extra", "~ main/Gain parameter expression 2 * in0 → 3 * in0");

        // meanwhile another tool changes the gain: the pending change no longer fits, so nothing is applied
        NetworkInfo base = network().snapshot();
        NetworkInfo other = base.copy();
        other.setParameters(ref("Gain"), List.of(Parameter.named("expression", "5 * in0")));
        assertThat(network().apply("another tool", base, other).executed()).isTrue();
        Thread.sleep(300); // let the session see the other tool's change (it conflicts, so it stays pending)

        ChangeOutcome refused = edt(session::deploy);
        assertThat(refused.executed()).isFalse();
        assertThat(network().snapshot().node(ref("Extra"))).as("all or nothing").isNull();
        assertThat(edt(session::collecting)).isTrue();
        assertThat(edt(() -> editor.network().node(ref("Extra")))).as("still pending here").isNotNull();

        // discard, collect again, and deploy what fits: both changes arrive together
        edt(() -> {
            session.discardPending();
            return null;
        });
        assertThat(eventually(() -> "5 * in0".equals(editor.network().node(ref("Gain")).parameter("expression")))).isTrue();
        ChangeOutcome deployed = edt(() -> {
            session.startCollecting();
            editor.setParameters(ref("Gain"), List.of(Parameter.named("expression", "4 * in0")));
            editor.addNode("main", NodeInfo.data("Extra", LIB + "DoubleData"));
            return session.deploy();
        });
        assertThat(deployed.executed()).as(deployed.toString()).isTrue();
        NetworkInfo running = network().snapshot();
        assertThat(running.node(ref("Extra"))).isNotNull();
        assertThat(running.node(ref("Gain")).parameter("expression")).isEqualTo("4 * in0");
        assertThat(edt(session::collecting)).as("live again").isFalse();
    }

    @Test
    void shouldStayOpenOfflineWithTheLastStateWhenTheNetworkIsLost() throws Exception {
        NetworkInfo last = edt(() -> editor.network().copy());

        run.close();

        assertThat(eventually(() -> heard.ended != null)).isTrue();
        assertThat(heard.lost).isTrue();
        assertThat(edt(editor::gate)).as("offline: edits apply here only").isNull();
        assertThat(edt(() -> editor.network().copy())).isEqualTo(last);
        assertThat(edt(() -> editor.addNode("main", NodeInfo.data("Offline", LIB + "DoubleData"))).accepted()).isTrue();
    }

    @Test
    void shouldDeployANetworkEditedOfflineAsTheDifferenceToTheRunningOne() throws Exception {
        edt(() -> {
            session.close();
            return null;
        });
        // edited offline: the same network from its file, with a new Data and the gain changed
        NetworkInfo offline = LiveTestNetwork.definition();
        offline.addNode("main", NodeInfo.data("Offline", LIB + "DoubleData"));
        offline.setParameters(ref("Gain"), List.of(Parameter.named("expression", "7 * in0")));
        UndoableNetworkEditor offlineEditor = edt(() -> new UndoableNetworkEditor(offline, new NetworkLayout()));
        GraphScene offlineScene = edt(() -> new GraphScene(offlineEditor));

        LiveSession deploying = edt(() -> LiveSession.attach(network(), offlineEditor, offlineScene, heard, true));
        assertThat(edt(() -> deploying.pending().entries()).stream().map(NetworkDiff.Entry::text))
                .containsExactlyInAnyOrder("+ node main/Offline", "~ main/Gain parameter expression 2 * in0 → 7 * in0");
        assertThat(network().snapshot().node(ref("Offline"))).as("nothing sent before Deploy").isNull();

        ChangeOutcome deployed = edt(deploying::deploy);

        assertThat(deployed.executed()).as(deployed.toString()).isTrue();
        assertThat(network().snapshot().node(ref("Offline"))).isNotNull();
        assertThat(network().snapshot().node(ref("Gain")).parameter("expression")).isEqualTo("7 * in0");
        assertThat(edt(deploying::collecting)).isFalse();
        session = deploying;
    }
}
