package org.fdnet.corba.control;

import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.fdnet.control.LocalLiveNetwork;
import org.fdnet.control.NetworkUnreachableException;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.testing.HeardFromNetwork;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;


/** The control object and its client in one JVM (two ORBs): the mapping of every call, without process start-up. */
@Timeout(60)
class ControlObjectInProcessTest {
    private static final String LIB = "org.fdnet.runtime.library.";

    @TempDir
    Path runDir;

    @BeforeEach
    void privateRunFolder() {
        System.setProperty(RunFiles.FOLDER_PROPERTY, runDir.toString());
    }

    @AfterEach
    void defaultRunFolder() {
        System.clearProperty(RunFiles.FOLDER_PROPERTY);
    }

    static NodeRef ref(String text) {
        return NodeRef.parse(text, "main");
    }

    static NetworkInfo network() {
        NetworkInfo n = new NetworkInfo("in-process");
        n.addNode("main", NodeInfo.data("In", LIB + "DoubleData"));
        n.addNode("main", NodeInfo.data("Out", LIB + "DoubleData"));
        n.addNode("main", NodeInfo.relation("Gain", LIB + "Expression", Parameter.named("expression", "2 * in0")));
        n.addConnection("main", ConnectionInfo.reader(ref("In"), ref("Gain")));
        n.addConnection("main", ConnectionInfo.writer(ref("Gain"), ref("Out")));
        return n;
    }


    @Test
    void shouldCarryEveryCallAndEveryNotificationThroughCorba() throws Exception {
        try (RuntimeNetwork net = RuntimeNetwork.start(network(), RuntimeOptions.defaults().workerThreads(1))) {
            LocalLiveNetwork local = new LocalLiveNetwork("in-process", net.controller());
            ControlPublication published = ControlPublication.atPort(local, "127.0.0.1", 0);
            try (RemoteLiveNetwork remote = RemoteLiveNetwork.attach("in-process", null)) {
                assertThat(remote.name()).isEqualTo("in-process");
                assertThat(remote.snapshot()).isEqualTo(net.controller().snapshot());
                assertThat(remote.loggerViewerAddress()).as("a run that knows no logger says none").isEmpty();
                HeardFromNetwork heard = new HeardFromNetwork();
                remote.subscribe(heard);

                assertThat(remote.send(ref("In"), "4").executed()).isTrue();
                Map<NodeRef, Value> sample = null;
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
                while (System.nanoTime() < deadline && (sample == null || !sample.containsKey(ref("Out"))
                        || sample.get(ref("Out")).asDouble() != 8.0)) {
                    sample = heard.samples.poll(200, TimeUnit.MILLISECONDS);
                }
                assertThat(sample).isNotNull();
                assertThat(sample.get(ref("Out")).asDouble()).isEqualTo(8.0);

                ChangeOutcome set = remote.setParameter(ref("Gain"), "expression", "3 * in0");
                assertThat(set.executed()).as(set.toString()).isTrue();
                assertThat(heard.changes.poll(10, TimeUnit.SECONDS)).isEqualTo(set);
                ChangeOutcome bad = remote.hold("NoSuchModule");
                assertThat(bad.executed()).isFalse();
                assertThat(bad.reason()).contains("NoSuchModule");

                published.close("the test stopped it");
                deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
                while (heard.disconnects.isEmpty() && System.nanoTime() < deadline) {
                    Thread.sleep(20);
                }
                assertThat(heard.disconnects).containsExactly("the test stopped it");
                assertThat(remote.hold("main").reason()).contains("in-process");
                assertThatThrownBy(remote::snapshot).isInstanceOf(NetworkUnreachableException.class);
            } finally {
                published.close();
            }
        }
    }

    @Test
    void shouldSayNoNetworkOfThatNameRunsHere() {
        assertThatThrownBy(() -> RemoteLiveNetwork.attach("nobody-runs-this", null))
                .isInstanceOf(NetworkUnreachableException.class)
                .hasMessageContaining("no network named 'nobody-runs-this' runs on this machine");
    }

    @Test
    void shouldListenForCallbacksOnLoopbackForANetworkOnThisMachine() {
        assertThat(RemoteLiveNetwork.callbackAddress("corbaloc::127.0.0.1:2809/FDNetControl")).isEqualTo("127.0.0.1");
        assertThat(RemoteLiveNetwork.callbackAddress("corbaloc:iiop:localhost:2809/NameService")).isEqualTo("127.0.0.1");
        assertThat(RemoteLiveNetwork.callbackAddress(null)).isEqualTo("127.0.0.1");
    }
}
