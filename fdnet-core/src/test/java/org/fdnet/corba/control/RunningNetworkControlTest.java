package org.fdnet.corba.control;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fdnet.control.NetworkUnreachableException;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.testing.CliRun;
import org.fdnet.testing.HeardFromNetwork;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import static org.assertj.core.api.Assertions.assertThat;


/**
 * The path users take: {@code fdnet run} in a process of its own publishes its control object on
 * {@code --control-port}; this JVM attaches to it as the editor or {@code fdnet control} does.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class RunningNetworkControlTest {
    private static final String LIB = "org.fdnet.runtime.library.";
    private static final NodeRef SIGNAL = ref("Wave/signal");

    @TempDir
    Path dir;

    private FdnetChildProcess run;
    private RemoteLiveNetwork network;
    private int port;

    static NodeRef ref(String text) {
        return NodeRef.parse(text, "main");
    }

    /** Module Wave: a 50 ms sine into Wave/signal, doubled by main/Gain into main/Out; main/Organizer filters sensors. */
    private Path networkFile() throws Exception {
        NetworkInfo n = new NetworkInfo("control-test-" + ProcessHandle.current().pid());
        n.addModule("Wave", true);
        n.addNode("Wave", NodeInfo.data("signal", LIB + "DoubleData"));
        n.addNode("Wave", NodeInfo.relation("source", LIB + "PeriodicSource", Parameter.named("period", "50")));
        n.addConnection("Wave", ConnectionInfo.writer(ref("Wave/source"), SIGNAL));
        n.addNode("main", NodeInfo.data("Out", LIB + "DoubleData"));
        n.addNode("main", NodeInfo.relation("Gain", LIB + "Expression", Parameter.named("expression", "2 * in0")));
        n.addConnection("main", ConnectionInfo.reader(SIGNAL, ref("Gain")));
        n.addConnection("main", ConnectionInfo.writer(ref("Gain"), ref("Out")));
        n.addNode("main", NodeInfo.relation("Organizer", LIB + "AutoFilter", Parameter.named("period", "20")));
        Path file = dir.resolve("control-test.fdn");
        NetworkRepository.save(n, file);
        return file;
    }

    /** What the run is told with --logger-viewer (no logger needs to listen there: the run only passes it on). */
    private static final String VIEWERS = "127.0.0.1:5599";

    @BeforeEach
    void startRun() throws Exception {
        port = FdnetChildProcess.freePort();
        run = FdnetChildProcess.start("fdnet run", List.of("run", networkFile().toString(), "--for", "110s",
                "--control-port", Integer.toString(port), "--logger-viewer", VIEWERS), "control object of", 60_000);
        network = RemoteLiveNetwork.attach("127.0.0.1:" + port, null);
    }

    @AfterEach
    void stop() {
        if (network != null) {
            network.close();
        }
        if (run != null) {
            run.close();
        }
    }


    @Test
    void shouldTellAToolWhereViewersReachTheRunsLogger() {
        assertThat(network.loggerViewerAddress()).contains(VIEWERS);
    }

    @Test
    void shouldAcceptALiveEditAndRefuseAnotherWithItsReasonChangingNothing() {
        NetworkInfo base = network.snapshot();
        NetworkInfo edited = base.copy();
        edited.setParameters(ref("Gain"), List.of(Parameter.named("expression", "3 * in0")));

        ChangeOutcome accepted = network.apply("triple the gain", base, edited);

        assertThat(accepted.executed()).as(accepted.toString()).isTrue();
        assertThat(network.snapshot().node(ref("Gain")).parameter("expression")).isEqualTo("3 * in0");

        NetworkInfo before = network.snapshot();
        NetworkInfo broken = before.copy();
        broken.addNode("main", NodeInfo.relation("Broken", LIB + "NoSuchRelation"));
        broken.setParameters(ref("Gain"), List.of(Parameter.named("expression", "4 * in0")));
        ChangeOutcome refused = network.apply("add a broken node", before, broken);

        assertThat(refused.executed()).isFalse();
        assertThat(refused.reason()).contains("NoSuchRelation");
        assertThat(network.snapshot()).isEqualTo(before);

        ChangeOutcome stale = network.apply("triple it from a stale base", base, edited);
        assertThat(stale.executed()).isFalse();
        assertThat(stale.reason()).contains("main/Gain", "in the running network");
        assertThat(network.snapshot()).isEqualTo(before);
    }

    @Test
    void shouldStopValuesWhenAModuleIsUnloadedAndLetThemFlowWhenItIsLoadedAgain() throws Exception {
        HeardFromNetwork heard = new HeardFromNetwork();
        network.subscribe(heard);
        assertThat(heard.sampleWith(SIGNAL, 15_000)).as("Wave/signal sampled while Wave runs").isTrue();

        CliRun cli = new CliRun();
        assertThat(cli.fdnet("control", "127.0.0.1:" + port, "unload", "Wave")).as(cli.output()).isZero();
        assertThat(cli.output()).contains("ok: unload module Wave");
        assertThat(heard.changeAbout("unload module Wave")).isNotNull();
        assertThat(network.loadedModules()).doesNotContain("Wave");
        heard.samples.clear();
        assertThat(heard.sampleWith(SIGNAL, 1_500)).as("no Wave/signal once Wave is unloaded (15 samples)").isFalse();

        assertThat(network.load("Wave").executed()).isTrue();
        assertThat(heard.sampleWith(SIGNAL, 15_000)).as("Wave/signal sampled again").isTrue();
        cli.clear();
        assertThat(cli.fdnet("control", "127.0.0.1:" + port, "unload", "NoSuchModule")).isEqualTo(1);
        assertThat(cli.output()).contains("refused: unload", "NoSuchModule");
    }

    @Test
    void shouldTellASubscriberWhatTheNetworkBuiltByItself() throws Exception {
        HeardFromNetwork heard = new HeardFromNetwork();
        network.subscribe(heard);
        NetworkInfo base = network.snapshot();
        NetworkInfo edited = base.copy();
        edited.addNode("main", NodeInfo.data("Wheel", LIB + "DoubleSensor"));
        assertThat(network.apply("plug a wheel sensor", base, edited).executed()).isTrue();

        // main/Organizer (AutoFilter) sees the sensor and pastes a filter for it: a change nobody outside asked for
        ChangeOutcome built = heard.changeAbout("Wheel filter");

        assertThat(built).as("the Organizer's own change reaches the subscriber").isNotNull();
        assertThat(built.executed()).isTrue();
        assertThat(network.snapshot().node(ref("Wheel filter"))).isNotNull();
    }

    @Test
    void shouldSayDisconnectedWithTheReasonWhenTheNetworkDiesAndRefuseEveryCall() throws Exception {
        HeardFromNetwork heard = new HeardFromNetwork();
        network.subscribe(heard);
        assertThat(heard.sampleWith(SIGNAL, 15_000)).isTrue();

        run.kill();

        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
        while (heard.disconnects.isEmpty() && System.nanoTime() < deadline) {
            Thread.sleep(50);
        }
        assertThat(heard.disconnects).hasSize(1);
        assertThat(heard.disconnects.get(0)).contains("127.0.0.1:" + port).contains("cannot be reached");
        ChangeOutcome afterDeath = network.hold("Wave");
        assertThat(afterDeath.executed()).isFalse();
        assertThat(afterDeath.reason()).isEqualTo(heard.disconnects.get(0));
        org.assertj.core.api.Assertions.assertThatThrownBy(network::snapshot)
                .isInstanceOf(NetworkUnreachableException.class).hasMessageContaining("127.0.0.1:" + port);
    }
}
