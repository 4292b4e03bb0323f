package org.fdnet.control;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.testing.HeardFromNetwork;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import static org.assertj.core.api.Assertions.assertThat;


@Timeout(60)
class LocalLiveNetworkTest {
    private static final String LIB = "org.fdnet.runtime.library.";

    static NodeRef ref(String text) {
        return NodeRef.parse(text, "main");
    }

    /** Module Wave: a 50 ms sine into Wave/signal, scaled by main/Gain into main/Out. */
    static NetworkInfo network() {
        NetworkInfo n = new NetworkInfo("live-test");
        n.addModule("Wave", true);
        n.addNode("Wave", NodeInfo.data("signal", LIB + "DoubleData"));
        n.addNode("Wave", NodeInfo.relation("source", LIB + "PeriodicSource", Parameter.named("period", "50")));
        n.addConnection("Wave", ConnectionInfo.writer(ref("Wave/source"), ref("Wave/signal")));
        n.addNode("main", NodeInfo.data("Out", LIB + "DoubleData"));
        n.addNode("main", NodeInfo.relation("Gain", LIB + "Expression", Parameter.named("expression", "2 * in0")));
        n.addConnection("main", ConnectionInfo.reader(ref("Wave/signal"), ref("Gain")));
        n.addConnection("main", ConnectionInfo.writer(ref("Gain"), ref("Out")));
        n.addNode("main", NodeInfo.relation("Organizer", LIB + "AutoFilter", Parameter.named("period", "20")));
        return n;
    }


    @Test
    void shouldApplyTheDifferenceOfAnEditAndRefuseOneThatNoLongerFits() throws Exception {
        try (RuntimeNetwork net = RuntimeNetwork.start(network(), RuntimeOptions.defaults().workerThreads(2));
             LocalLiveNetwork live = new LocalLiveNetwork("live-test", net.controller())) {
            HeardFromNetwork heard = new HeardFromNetwork();
            live.subscribe(heard);
            NetworkInfo base = live.snapshot();
            NetworkInfo edited = base.copy();
            edited.setParameters(ref("Gain"), List.of(Parameter.named("expression", "3 * in0")));

            ChangeOutcome accepted = live.apply("triple the gain", base, edited);

            assertThat(accepted.executed()).as(accepted.toString()).isTrue();
            assertThat(live.snapshot().node(ref("Gain")).parameter("expression")).isEqualTo("3 * in0");
            assertThat(heard.changeAbout("triple the gain")).isEqualTo(accepted);

            // the same edit again, from the same (now stale) base: the running gain is no longer 2 * in0
            NetworkInfo before = live.snapshot();
            ChangeOutcome refused = live.apply("triple it again", base, edited);
            assertThat(refused.executed()).isFalse();
            assertThat(refused.reason()).contains("main/Gain", "3 * in0", "2 * in0");
            assertThat(live.snapshot()).isEqualTo(before);
        }
    }

    @Test
    void shouldStopAndRestartValuesWhenAModuleIsUnloadedAndLoaded() throws Exception {
        try (RuntimeNetwork net = RuntimeNetwork.start(network(), RuntimeOptions.defaults().workerThreads(2));
             LocalLiveNetwork live = new LocalLiveNetwork("live-test", net.controller())) {
            HeardFromNetwork heard = new HeardFromNetwork();
            AutoCloseable subscription = live.subscribe(heard);
            assertThat(heard.sampleWith(ref("Wave/signal"))).as("Wave/signal sampled").isTrue();

            assertThat(live.unload("Wave").executed()).isTrue();
            assertThat(heard.changeAbout("Wave")).isNotNull();
            heard.samples.clear();
            assertThat(heard.sampleWith(ref("Wave/signal"), 1_000)).as("no Wave/signal once unloaded (ten samples)").isFalse();

            assertThat(live.load("Wave").executed()).isTrue();
            assertThat(heard.sampleWith(ref("Wave/signal"))).as("Wave/signal sampled again").isTrue();
            subscription.close();
        }
    }

    @Test
    void shouldTellASubscriberWhatTheNetworkBuiltByItselfAndThatItStopped() throws Exception {
        try (RuntimeNetwork net = RuntimeNetwork.start(network(), RuntimeOptions.defaults().workerThreads(2));
             LocalLiveNetwork live = new LocalLiveNetwork("live-test", net.controller())) {
            HeardFromNetwork heard = new HeardFromNetwork();
            live.subscribe(heard);
            NetworkInfo base = live.snapshot();
            NetworkInfo edited = base.copy();
            edited.addNode("main", NodeInfo.data("Wheel", LIB + "DoubleSensor"));
            assertThat(live.apply("plug a wheel sensor", base, edited).executed()).isTrue();

            ChangeOutcome built = heard.changeAbout("Wheel filter");
            assertThat(built).as("the Organizer's own change, told to the subscriber").isNotNull();
            assertThat(built.executed()).isTrue();

            live.networkStopped("the run ended");
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (heard.disconnects.isEmpty() && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            assertThat(heard.disconnects).containsExactly("the run ended");
        }
    }
}
