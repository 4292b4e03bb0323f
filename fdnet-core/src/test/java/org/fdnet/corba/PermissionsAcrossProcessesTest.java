package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fdnet.corba.control.RemoteLiveNetwork;
import org.fdnet.corba.idl.ChangeOp;
import org.fdnet.corba.idl.ChangeRequest;
import org.fdnet.corba.idl.ConnectionSpec;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.NodeSpec;
import org.fdnet.corba.idl.Value;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.tls.TestKeys;
import org.fdnet.tls.TlsIdentity;
import org.fdnet.tls.TransportSecurity;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.Timeout;
import org.omg.CORBA.NO_PERMISSION;

/**
 * A network whose permissions file limits its members, with a naming service, a host and a run (its control object)
 * as child processes speaking TLS: the viewer's certificate reads but cannot write a Data (directly, by a link's
 * delivery, or through the control object), nor reshape the host; an operator limited to module Walk cannot unload
 * Gait but can hold and unload Walk; every refusal names the certificate, the node or module and the right, and
 * nothing refused is applied.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
@Timeout(value = 240, unit = TimeUnit.SECONDS)
class PermissionsAcrossProcessesTest {
    /** Every member reads everything; the operator's certificate (the run's, the test's own calls) may do anything. */
    static final String OPERATOR_DOES_EVERYTHING = """
            *         read     *
            operator  write    *
            operator  load     *
            operator  unload   *
            operator  reshape  *
            """;
    private static final String GRANTS = OPERATOR_DOES_EVERYTHING + """
            walker    load     Walk
            walker    unload   Walk
            walker    reshape  Walk
            """;
    private static final NodeRef CERTAINTY = new NodeRef("main", "Certainty");
    private static final String LIB = "org.fdnet.runtime.library.";

    private final List<AutoCloseable> processes = new ArrayList<>();
    private final List<AutoCloseable> orbs = new ArrayList<>();
    private Path keys;
    private String naming;

    @BeforeAll
    void startNamingAndHost() {
        keys = TestKeys.withPermissions("permissions-limited", GRANTS,
                List.of("naming", "crawler", "operator", "viewer", "walker"));
        int port = FdnetChildProcess.freePort();
        naming = "corbaloc::127.0.0.1:" + port + "/NameService";
        processes.add(FdnetChildProcess.start("naming", List.of("naming", "--port", Integer.toString(port), "--tls",
                store("naming")), "fdnet naming ready", 60_000));
        processes.add(FdnetChildProcess.start("crawler", List.of("host", "--name", "crawler", "--naming", naming,
                "--tls", store("crawler")), "fdnet host crawler ready", 60_000));
    }

    @AfterEach
    void closeOrbs() throws Exception {
        for (AutoCloseable orb : orbs) {
            orb.close();
        }
        orbs.clear();
        TransportSecurity.off();
    }

    @AfterAll
    void stopProcesses() throws Exception {
        for (int i = processes.size() - 1; i >= 0; i--) {
            processes.get(i).close();
        }
    }

    @Test
    void shouldRefuseTheViewersWritesAndApplyNoneOfThem() throws Exception {
        Host asOperator = crawlerAs("operator");
        asOperator.createNode(IdlMapping.spec("main", NodeInfo.data("Certainty", "DoubleData")));
        asOperator.write(IdlMapping.id(CERTAINTY), ValueCodec.encode(0.25));
        asOperator.acceptLink(7, IdlMapping.id(CERTAINTY), "flyer");

        Host asViewer = crawlerAs("viewer");
        assertThat(ValueCodec.decode(asViewer.read(IdlMapping.id(CERTAINTY)))).as("the viewer may read").isEqualTo(0.25);
        assertThatThrownBy(() -> asViewer.write(IdlMapping.id(CERTAINTY), ValueCodec.encode(1.0)))
                .isInstanceOf(NO_PERMISSION.class)
                .hasMessageContaining("certificate 'viewer' may not write main/Certainty");
        ValueBatch batch = new ValueBatch(7, 0, "flyer#1#7", 0, new Value[] {ValueCodec.encode(2.0)});
        assertThatThrownBy(() -> asViewer.deliver(batch)).as("a link's values into the Data")
                .isInstanceOf(NO_PERMISSION.class)
                .hasMessageContaining("certificate 'viewer' may not write main/Certainty");
        assertThatThrownBy(() -> asViewer.createNode(IdlMapping.spec("main", NodeInfo.data("Map", "DoubleData"))))
                .isInstanceOf(NO_PERMISSION.class).hasMessageContaining("certificate 'viewer' may not reshape module main");
        assertThatThrownBy(() -> asViewer.answerMessage("Visitor", "nodes", ValueCodec.encode(0.0)))
                .as("a servant message").isInstanceOf(NO_PERMISSION.class)
                .hasMessageContaining("certificate 'viewer' may not reshape module *");

        Host again = crawlerAs("operator");
        assertThat(ValueCodec.decode(again.read(IdlMapping.id(CERTAINTY)))).as("nothing refused was applied")
                .isEqualTo(0.25);
        assertThat(again.nodes()).doesNotContain("main/Map");
        assertThat(again.deliver(batch)).as("the operator's delivery on the same link").isEqualTo(1);
        assertThat(ValueCodec.decode(again.read(IdlMapping.id(CERTAINTY)))).isEqualTo(2.0);
    }

    @Test
    void shouldLetAnOperatorLimitedToWalkUnloadWalkButNotGaitOnAHost() throws Exception {
        Host asOperator = crawlerAs("operator");
        asOperator.loadModule("Walk", new NodeSpec[] {IdlMapping.spec("Walk", NodeInfo.data("Speed", "DoubleData"))},
                new ConnectionSpec[0]);
        asOperator.loadModule("Gait", new NodeSpec[] {IdlMapping.spec("Gait", NodeInfo.data("Phase", "DoubleData"))},
                new ConnectionSpec[0]);

        Host asWalker = crawlerAs("walker");
        assertThatThrownBy(() -> asWalker.unloadModule("Gait")).isInstanceOf(NO_PERMISSION.class)
                .hasMessageContaining("certificate 'walker' may not unload module Gait");
        assertThatThrownBy(() -> asWalker.write(IdlMapping.id(new NodeRef("Walk", "Speed")), ValueCodec.encode(1.0)))
                .isInstanceOf(NO_PERMISSION.class).hasMessageContaining("may not write Walk/Speed");
        assertThat(asWalker.nodes()).contains("Gait/Phase", "Walk/Speed");
        ChangeRequest holdGait = new ChangeRequest(41, ChangeOp.CO_HOLD, "Gait", IdlMapping.id(CERTAINTY), "", "");
        assertThatThrownBy(() -> asWalker.prepareChange(holdGait)).isInstanceOf(NO_PERMISSION.class)
                .hasMessageContaining("certificate 'walker' may not reshape module Gait");
        assertThat(asOperator.prepareChange(holdGait)).as("the operator prepares it").isEmpty();
        assertThatThrownBy(() -> asWalker.commitChange(41)).as("a change another certificate prepared")
                .isInstanceOf(NO_PERMISSION.class).hasMessageContaining("certificate 'operator' prepared it");
        assertThatThrownBy(() -> asWalker.abortChange(41)).isInstanceOf(NO_PERMISSION.class);
        asOperator.abortChange(41);
        asWalker.unloadModule("Walk");
        assertThat(asWalker.nodes()).contains("Gait/Phase").doesNotContain("Walk/Speed");
    }

    @Test
    void shouldRefuseAtTheControlObjectWhatTheToolsCertificateMayNotChange() throws Exception {
        int port = FdnetChildProcess.freePort();
        try (FdnetChildProcess run = FdnetChildProcess.start("fdnet run", List.of("run", networkFile().toString(),
                "--for", "200s", "--control-port", Integer.toString(port), "--tls", store("operator")),
                "control object of", 60_000)) {
            TransportSecurity.use(TlsIdentity.load(keys.resolve("walker.p12")));
            RemoteLiveNetwork asWalker = RemoteLiveNetwork.attach("127.0.0.1:" + port, null);
            orbs.add(asWalker::close);
            ChangeOutcome gait = asWalker.unload("Gait");
            assertThat(gait.executed()).isFalse();
            assertThat(gait.reason()).contains("certificate 'walker' may not unload module Gait");
            assertThat(asWalker.loadedModules()).contains("Gait", "Walk");
            assertThat(asWalker.setParameter(new NodeRef("Gait", "Phase"), "x", "1").reason())
                    .contains("certificate 'walker' may not reshape module Gait");
            assertThat(asWalker.send(CERTAINTY, "0.5").reason()).contains("certificate 'walker' may not write main/Certainty");
            NetworkInfo base = asWalker.snapshot();
            NetworkInfo gaitEdited = copyOf(base);
            gaitEdited.addNode("Gait", NodeInfo.data("Extra", LIB + "DoubleData"));
            assertThat(asWalker.apply("add Gait/Extra", base, gaitEdited).reason()).as("an edit of Gait")
                    .contains("certificate 'walker' may not reshape module Gait");
            NetworkInfo walkEdited = copyOf(base);
            walkEdited.addNode("Walk", NodeInfo.data("Extra", LIB + "DoubleData"));
            ChangeOutcome walkEdit = asWalker.apply("add Walk/Extra", base, walkEdited);
            assertThat(walkEdit.executed()).as("an edit of Walk: " + walkEdit.reason()).isTrue();
            assertThat(asWalker.snapshot().module("Gait").node("Extra")).as("nothing refused was applied").isNull();
            assertThat(asWalker.hold("Walk").executed()).as("walker may reshape Walk").isTrue();
            assertThat(asWalker.resume("Walk").executed()).isTrue();
            assertThat(asWalker.unload("Walk").executed()).as("walker may unload Walk").isTrue();
            assertThat(asWalker.loadedModules()).contains("Gait").doesNotContain("Walk");
        }
    }

    private static NetworkInfo copyOf(NetworkInfo network) throws Exception {
        return NetworkRepository.fromText(NetworkRepository.toText(network), "a copy");
    }

    /** Modules Walk and Gait, a Data each, loaded at start; main/Certainty. */
    private Path networkFile() throws Exception {
        NetworkInfo n = new NetworkInfo("permissions-test-" + ProcessHandle.current().pid());
        n.addModule("Walk", true);
        n.addNode("Walk", NodeInfo.data("Speed", LIB + "DoubleData"));
        n.addModule("Gait", true);
        n.addNode("Gait", NodeInfo.data("Phase", LIB + "DoubleData"));
        n.addNode("main", NodeInfo.data("Certainty", LIB + "DoubleData"));
        Path file = keys.resolve("permissions-test.fdn");
        NetworkRepository.save(n, file);
        return file;
    }

    /** Host crawler as reached by the member {@code name}, on an ORB of its own (a connection of its own). */
    private Host crawlerAs(String name) {
        TransportSecurity.use(TlsIdentity.load(keys.resolve(name + ".p12")));
        OrbRuntime orb = OrbRuntime.start(OrbSettings.defaults().withNaming(naming).withCallTimeoutMillis(10_000));
        orbs.add(orb);
        return HostDirectory.connect(orb).find("crawler").orElseThrow();
    }

    private String store(String name) {
        return keys.resolve(name + ".p12").toString();
    }
}
