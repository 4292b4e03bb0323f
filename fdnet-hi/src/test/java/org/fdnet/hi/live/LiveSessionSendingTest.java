package org.fdnet.hi.live;

import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.hi.live.LiveTestNetwork.edt;
import static org.fdnet.hi.live.LiveTestNetwork.eventually;
import static org.fdnet.hi.live.LiveTestNetwork.ref;

import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import org.fdnet.control.LiveNetwork;
import org.fdnet.control.LiveNetworkListener;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.edit.UndoableNetworkEditor;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkEdit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A network that takes its time to answer (as one in another process may, up to the call timeout) does not hold the
 * Swing thread: while an edit is being sent the window keeps dispatching events, the status bar says it is sending,
 * the view is unchanged, and another change meanwhile is refused at once; the edit shows once it was executed.
 */
@Timeout(60)
class LiveSessionSendingTest {

    @Test
    void shouldKeepTheSwingThreadFreeWhileAnEditIsSentAndShowItOnlyOnceExecuted() throws Exception {
        LiveSessionTest.Heard heard = new LiveSessionTest.Heard();
        try (InProcessRun run = LiveTestNetwork.start()) {
            SlowNetwork slow = new SlowNetwork(run.live());
            UndoableNetworkEditor editor = edt(() -> new UndoableNetworkEditor(LiveTestNetwork.definition(),
                    new NetworkLayout()));
            LiveSession session = edt(() -> LiveSession.attach(slow, editor, new GraphScene(editor), heard, false));
            try {
                AtomicReference<EditResult> result = new AtomicReference<>();
                SwingUtilities.invokeLater(() -> result.set(editor.setParameters(ref("Gain"),
                        List.of(Parameter.named("expression", "3 * in0")))));
                assertThat(slow.applying.await(10, TimeUnit.SECONDS)).as("the edit reached the network").isTrue();

                CountDownLatch dispatched = new CountDownLatch(1);
                AtomicReference<String> shown = new AtomicReference<>();
                AtomicReference<EditResult> second = new AtomicReference<>();
                AtomicReference<ChangeOutcome> command = new AtomicReference<>();
                SwingUtilities.invokeLater(() -> {
                    shown.set(editor.network().node(ref("Gain")).parameter("expression"));
                    second.set(editor.setParameters(ref("Gain"), List.of(Parameter.named("expression", "5 * in0"))));
                    command.set(session.hold("Wave"));
                    dispatched.countDown();
                });
                assertThat(dispatched.await(5, TimeUnit.SECONDS)).as("the Swing thread dispatches events meanwhile")
                        .isTrue();
                assertThat(result.get()).as("the edit is still under way").isNull();
                assertThat(shown.get()).as("the view is unchanged while sending").isEqualTo("2 * in0");
                assertThat(heard.infos).anyMatch(m -> m.startsWith("Sending to live-editor-test: "));
                assertThat(second.get().accepted()).as("a second edit meanwhile").isFalse();
                assertThat(second.get().reason()).contains("still sending the previous change");
                assertThat(command.get().executed()).as("a module command meanwhile").isFalse();
                assertThat(command.get().reason()).contains("still sending the previous change");

                slow.release.countDown();
                assertThat(eventually(() -> result.get() != null)).isTrue();
                assertThat(result.get().accepted()).as(String.valueOf(result.get().reason())).isTrue();
                assertThat(edt(() -> editor.network().node(ref("Gain")).parameter("expression"))).isEqualTo("3 * in0");
                assertThat(run.live().snapshot().node(ref("Gain")).parameter("expression")).isEqualTo("3 * in0");
                assertThat(run.live().heldModules()).as("the refused hold was not sent").isEmpty();
                assertThat(heard.infos).anyMatch(m -> m.startsWith("Executed by live-editor-test: "));
            } finally {
                slow.release.countDown();
                edt(() -> {
                    session.close();
                    return null;
                });
            }
        }
    }

    /** The running network, whose first {@code apply} waits until the test releases it. */
    private static final class SlowNetwork implements LiveNetwork {
        final CountDownLatch applying = new CountDownLatch(1);
        final CountDownLatch release = new CountDownLatch(1);
        private final LiveNetwork network;

        SlowNetwork(LiveNetwork network) {
            this.network = network;
        }

        @Override
        public ChangeOutcome apply(String description, NetworkInfo base, NetworkInfo edited) {
            applying.countDown();
            try {
                release.await(30, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            return network.apply(description, base, edited);
        }

        @Override
        public String name() {
            return network.name();
        }

        @Override
        public NetworkInfo snapshot() {
            return network.snapshot();
        }

        @Override
        public Set<String> loadedModules() {
            return network.loadedModules();
        }

        @Override
        public Set<String> heldModules() {
            return network.heldModules();
        }

        @Override
        public Optional<String> loggerViewerAddress() {
            return network.loggerViewerAddress();
        }

        @Override
        public AutoCloseable subscribe(LiveNetworkListener listener) {
            return network.subscribe(listener);
        }

        @Override
        public ChangeOutcome apply(String description, NetworkEdit edit) {
            return network.apply(description, edit);
        }

        @Override
        public ChangeOutcome load(String module) {
            return network.load(module);
        }

        @Override
        public ChangeOutcome unload(String module) {
            return network.unload(module);
        }

        @Override
        public ChangeOutcome hold(String module) {
            return network.hold(module);
        }

        @Override
        public ChangeOutcome resume(String module) {
            return network.resume(module);
        }

        @Override
        public ChangeOutcome setParameter(NodeRef node, String parameter, String value) {
            return network.setParameter(node, parameter, value);
        }

        @Override
        public ChangeOutcome send(NodeRef data, String text) {
            return network.send(data, text);
        }

        @Override
        public void close() {
            // the run is closed by the test
        }
    }
}
