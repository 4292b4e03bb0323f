package org.fdnet.hi.live;

import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.hi.live.LiveTestNetwork.LIB;
import static org.fdnet.hi.live.LiveTestNetwork.edt;
import static org.fdnet.hi.live.LiveTestNetwork.eventually;
import static org.fdnet.hi.live.LiveTestNetwork.ref;

import java.util.List;
import org.fdnet.control.LocalLiveNetwork;
import org.fdnet.corba.control.ControlPublication;
import org.fdnet.corba.control.RemoteLiveNetwork;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.edit.UndoableNetworkEditor;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The editor's session through the network's CORBA control object, as {@code fdnet hi --attach} uses it: the
 * network is published on a free port of 127.0.0.1 in this JVM and reached through a real ORB.
 */
@Timeout(60)
class LiveSessionOverCorbaTest {

    @Test
    void shouldEditFollowAndGoOfflineThroughTheControlObject() throws Exception {
        NetworkInfo definition = LiveTestNetwork.definition();
        definition.setName("live-editor-corba-test");
        try (RuntimeNetwork net = RuntimeNetwork.start(definition, RuntimeOptions.defaults().workerThreads(2))) {
            LocalLiveNetwork local = new LocalLiveNetwork("live-editor-corba-test", net.controller());
            ControlPublication published = ControlPublication.atPort(local, "127.0.0.1", 0);
            try {
                RemoteLiveNetwork remote = RemoteLiveNetwork.attach(published.address(), null);
                LiveSessionTest.Heard heard = new LiveSessionTest.Heard();
                UndoableNetworkEditor editor = edt(() -> new UndoableNetworkEditor(new NetworkInfo("other"), new NetworkLayout()));
                GraphScene scene = edt(() -> new GraphScene(editor));
                edt(() -> LiveSession.attach(remote, editor, scene, heard, false));
                assertThat(edt(() -> editor.network().node(ref("Gain")))).as("the snapshot came over").isNotNull();

                EditResult accepted = edt(() -> editor.setParameters(ref("Gain"), List.of(Parameter.named("expression", "3 * in0"))));
                assertThat(accepted.accepted()).as(String.valueOf(accepted.reason())).isTrue();
                assertThat(net.controller().snapshot().node(ref("Gain")).parameter("expression")).isEqualTo("3 * in0");

                EditResult refused = edt(() -> editor.addNode("main", NodeInfo.relation("Broken", "org.fdnet.NoSuchRelation")));
                assertThat(refused.accepted()).isFalse();
                assertThat(refused.reason()).contains("org.fdnet.NoSuchRelation");
                assertThat(edt(() -> editor.network().node(ref("Broken")))).isNull();

                NetworkInfo base = local.snapshot();
                NetworkInfo plugged = base.copy();
                plugged.addNode("main", NodeInfo.data("Wheel", LIB + "DoubleSensor"));
                assertThat(local.apply("plug a wheel sensor", base, plugged).executed()).isTrue();
                assertThat(eventually(() -> editor.network().node(ref("Wheel filter")) != null))
                        .as("what the network built arrives through CORBA").isTrue();
                assertThat(eventually(() -> scene.liveValue(ref("Wave/signal")) != null)).as("live values arrive").isTrue();

                published.close("the run was stopped");
                assertThat(eventually(() -> heard.ended != null)).isTrue();
                assertThat(heard.lost).isTrue();
                assertThat(heard.ended).contains("the run was stopped");
                assertThat(edt(() -> editor.network().node(ref("Wheel filter")))).as("the last state stays").isNotNull();
                assertThat(edt(editor::gate)).isNull();
            } finally {
                published.close();
            }
        }
    }
}
