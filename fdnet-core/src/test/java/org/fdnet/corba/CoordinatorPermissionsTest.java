package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.ModuleOp;
import org.fdnet.corba.idl.NetworkCoordinator;
import org.fdnet.corba.idl.NetworkCoordinatorHelper;
import org.fdnet.corba.idl.NetworkDescription;
import org.fdnet.corba.idl.Outcome;
import org.fdnet.corba.idl.UnknownServant;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.WholeNetwork;
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
 * The network coordinator (what {@code fdnet run} serves to every host's Servants) under a permissions file, over TLS:
 * the test JVM coordinates as host "base" with the operator's certificate, host "crawler" is a child process, and each
 * caller reaches the coordinator on an ORB of its own with its own certificate. A walker limited to module Walk is
 * refused reading a Data of Gait, editing Gait (or Walk so that a Relation writes Gait's Data), unloading, holding and
 * resuming Gait, loading Spare and sending a servant message, with a reason naming the certificate, the node or module and the right; nothing refused reaches a host; the
 * same operations on Walk (or by the operator) are done.
 *
 * <pre>
 *   crawler: Walk/Speed, Gait/Phase (loaded at start), Spare/Idle (not loaded)     base: main/Here
 * </pre>
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
@Timeout(value = 240, unit = TimeUnit.SECONDS)
class CoordinatorPermissionsTest {
    /** The operator may do anything; the walker reads, loads, unloads and reshapes module Walk only. */
    private static final String GRANTS = """
            operator  read     *
            operator  write    *
            operator  load     *
            operator  unload   *
            operator  reshape  *
            walker    read     Walk
            walker    load     Walk
            walker    unload   Walk
            walker    reshape  Walk
            """;
    private static final String NO_LOOPBACK = "jacorb.iiop.enable_loopback";
    private static final NodeRef SPEED = new NodeRef("Walk", "Speed");
    private static final NodeRef PHASE = new NodeRef("Gait", "Phase");

    private final List<AutoCloseable> processes = new ArrayList<>();
    private final List<AutoCloseable> orbs = new ArrayList<>();
    private Path keys;
    private String naming;
    private HostProcess base;
    private NetworkDeployment deployment;
    private String coordinator;

    @BeforeAll
    void deployOverTls() throws Exception {
        keys = TestKeys.withPermissions("permissions-coordinator", GRANTS,
                List.of("naming", "crawler", "operator", "walker"));
        int port = FdnetChildProcess.freePort();
        naming = OrbSettings.namingCorbaloc(OrbSettings.LOOPBACK, port);
        processes.add(FdnetChildProcess.start("naming", List.of("naming", "--port", Integer.toString(port), "--tls",
                store("naming")), "fdnet naming ready", 60_000));
        processes.add(FdnetChildProcess.start("crawler", List.of("host", "--name", "crawler", "--naming", naming,
                "--tls", store("crawler")), "fdnet host crawler ready", 60_000));
        useCertificate("operator");
        OrbSettings settings = OrbSettings.defaults().withNaming(naming).withCallTimeoutMillis(10_000);
        // JacORB would hand the test's calls to host base over in memory (it is in this JVM), where no TLS session names
        // the caller and the coordinator would take every call for its own process's: base listens without that
        // loopback, so every call travels a TLS connection as it does between processes
        System.setProperty(NO_LOOPBACK, "off");
        try {
            base = HostProcess.start("base", settings, LocalNetworks.forHost("base", List.of()),
                    new ClassPolicy(List.of()), LinkSettings.defaults());
        } finally {
            System.clearProperty(NO_LOOPBACK);
        }
        processes.add(base);
        deployment = NetworkDeployment.start(DeploymentPlan.of(network(), "base", Set.of()),
                HostDirectory.connect(base.orb()), Map.of("base", base.reference()), DeploymentListener.quiet(),
                new MemoryEventSink(), 4, 10_000, 100);
        processes.add(deployment::close);
        NetworkCoordinator ref = CoordinatorServant.publish(base.orb(), new DistributedControl(deployment));
        coordinator = base.orb().orb().object_to_string(ref);
    }

    @AfterEach
    void closeOrbs() throws Exception {
        for (AutoCloseable orb : orbs) {
            orb.close();
        }
        orbs.clear();
        useCertificate("operator"); // the coordinator's own calls to the hosts stay the operator's
    }

    @AfterAll
    void stopProcesses() throws Exception {
        for (int i = processes.size() - 1; i >= 0; i--) {
            processes.get(i).close();
        }
        TransportSecurity.off();
    }

    @Test
    void shouldRefuseReadingADataOutsideTheCertificatesReadGrantAndReadOneInside() throws Exception {
        Host asOperator = crawlerAs("operator");
        asOperator.write(IdlMapping.id(SPEED), ValueCodec.encode(0.75));
        asOperator.write(IdlMapping.id(PHASE), ValueCodec.encode(0.25));
        NetworkCoordinator asWalker = coordinatorAs("walker");
        assertThatThrownBy(() -> asWalker.read(IdlMapping.id(PHASE))).isInstanceOf(NO_PERMISSION.class)
                .hasMessageContaining("certificate 'walker' may not read Gait/Phase");
        assertThat(ValueCodec.decode(asWalker.read(IdlMapping.id(SPEED)))).isEqualTo(0.75);
        assertThat(ValueCodec.decode(coordinatorAs("operator").read(IdlMapping.id(PHASE)))).isEqualTo(0.25);
    }

    @Test
    void shouldRefuseAnEditOfAModuleTheCertificateMayNotReshapeChangingNothingAndApplyOneOfItsOwn() throws Exception {
        NetworkCoordinator asWalker = coordinatorAs("walker");
        NetworkDescription before = asWalker.describeNetwork();
        Outcome gait = asWalker.applyEdit("add Gait/Extra", before.version, edited(before, "Gait"));
        assertThat(gait.executed).isFalse();
        assertThat(gait.text).contains("certificate 'walker' may not reshape module Gait")
                .endsWith("nothing changed on any host");
        assertThat(asWalker.describeNetwork().version).as("the network's version").isEqualTo(before.version);
        assertThat(crawlerNodes()).as("crawler runs").doesNotContain("Gait/Extra");

        Outcome walk = asWalker.applyEdit("add Walk/Extra", before.version, edited(before, "Walk"));
        assertThat(walk.executed).as(walk.text).isTrue();
        assertThat(crawlerNodes()).contains("Walk/Extra").doesNotContain("Gait/Extra");

        // a Relation of Walk that would write Gait's Data reshapes Gait too
        NetworkDescription now = asWalker.describeNetwork();
        Outcome intoGait = asWalker.applyEdit("add Walk/Pusher", now.version, withPusher(now));
        assertRefused(intoGait, "certificate 'walker' may not reshape module Gait");
        assertThat(crawlerNodes()).doesNotContain("Walk/Pusher");
        assertDone(coordinatorAs("operator").applyEdit("add Walk/Pusher", now.version, withPusher(now)));
        assertThat(crawlerNodes()).contains("Walk/Pusher");
    }

    @Test
    void shouldRefuseChangingAModuleWithoutItsRightLeavingItAsItWasAndChangeOneItMay() throws Exception {
        NetworkCoordinator asWalker = coordinatorAs("walker");
        assertRefused(asWalker.changeModule(ModuleOp.MO_UNLOAD, "Gait"), "certificate 'walker' may not unload module Gait");
        assertRefused(asWalker.changeModule(ModuleOp.MO_HOLD, "Gait"), "certificate 'walker' may not reshape module Gait");
        assertRefused(asWalker.changeModule(ModuleOp.MO_RESUME, "Gait"), "certificate 'walker' may not reshape module Gait");
        assertRefused(asWalker.changeModule(ModuleOp.MO_LOAD, "Spare"), "certificate 'walker' may not load module Spare");
        assertThat(crawlerNodes()).as("crawler runs").contains(PHASE.toString())
                .doesNotContain("Spare/Idle");

        assertDone(asWalker.changeModule(ModuleOp.MO_HOLD, "Walk"));
        assertDone(asWalker.changeModule(ModuleOp.MO_RESUME, "Walk"));
        assertDone(asWalker.changeModule(ModuleOp.MO_UNLOAD, "Walk"));
        assertThat(crawlerNodes()).doesNotContain(SPEED.toString()).contains(PHASE.toString());
        assertDone(asWalker.changeModule(ModuleOp.MO_LOAD, "Walk"));
        assertThat(crawlerNodes()).contains(SPEED.toString());
        NetworkCoordinator asOperator = coordinatorAs("operator");
        assertDone(asOperator.changeModule(ModuleOp.MO_LOAD, "Spare"));
        assertThat(crawlerNodes()).contains("Spare/Idle");
        assertDone(asOperator.changeModule(ModuleOp.MO_UNLOAD, "Spare"));
    }

    @Test
    void shouldRefuseAServantMessageToACertificateThatMayNotReshapeEveryModule() throws Exception {
        List<String> nodes = crawlerNodes();
        assertThatThrownBy(() -> coordinatorAs("walker").sendMessage("base", "Nowhere", "nodes", ValueCodec.encode(0.0)))
                .isInstanceOf(NO_PERMISSION.class).hasMessageContaining("certificate 'walker' may not reshape module *");
        assertThat(crawlerNodes()).as("crawler runs").containsExactlyInAnyOrderElementsOf(nodes);
        assertThatThrownBy(() -> coordinatorAs("operator").sendMessage("base", "Nowhere", "nodes",
                ValueCodec.encode(0.0))).as("the operator's message reaches the hosts, which have no such servant")
                .isInstanceOf(UnknownServant.class);
    }

    private static void assertRefused(Outcome outcome, String reason) {
        assertThat(outcome.executed).as(outcome.text).isFalse();
        assertThat(outcome.text).contains(reason);
    }

    private static void assertDone(Outcome outcome) {
        assertThat(outcome.executed).as(outcome.text).isTrue();
    }

    /** The network as described, with one more Data in {@code module} on crawler. */
    private static NetworkDescription edited(NetworkDescription description, String module) {
        WholeNetwork.Snapshot now = NetworkDescriptions.decode(description);
        NetworkInfo after = now.definition().copy();
        after.addNode(module, new NodeInfo(NodeKind.DATA, "Extra", "crawler", "", "DoubleData", List.of()));
        return NetworkDescriptions.encode(description.version, new WholeNetwork.Snapshot(after, now.loaded(),
                now.placedOn()));
    }

    /** The network as described, with a Relation of Walk on crawler that reads Walk/Speed and writes Gait/Phase. */
    private static NetworkDescription withPusher(NetworkDescription description) {
        WholeNetwork.Snapshot now = NetworkDescriptions.decode(description);
        NetworkInfo after = now.definition().copy();
        NodeRef pusher = after.addNode("Walk", new NodeInfo(NodeKind.RELATION, "Pusher", "crawler", "", "Expression",
                List.of(Parameter.named("expression", "in0 * 2"))));
        after.addConnection("Walk", ConnectionInfo.reader(SPEED, pusher));
        after.addConnection("Walk", ConnectionInfo.writer(pusher, PHASE));
        return NetworkDescriptions.encode(description.version, new WholeNetwork.Snapshot(after, now.loaded(),
                now.placedOn()));
    }

    private static NetworkInfo network() {
        NetworkInfo n = new NetworkInfo("coordinator-permissions");
        n.addModule("Walk", true);
        n.addNode("Walk", new NodeInfo(NodeKind.DATA, "Speed", "crawler", "", "DoubleData", List.of()));
        n.addModule("Gait", true);
        n.addNode("Gait", new NodeInfo(NodeKind.DATA, "Phase", "crawler", "", "DoubleData", List.of()));
        n.addModule("Spare", false);
        n.addNode("Spare", new NodeInfo(NodeKind.DATA, "Idle", "crawler", "", "DoubleData", List.of()));
        n.addNode("main", NodeInfo.data("Here", "DoubleData"));
        return n;
    }

    /**
     * The coordinator as reached by the member {@code name}, on an ORB of its own: its connection is made with that
     * member's certificate, then this JVM's own certificate is the operator's again, so the coordinator can only learn
     * the caller from the connection's TLS session.
     */
    private NetworkCoordinator coordinatorAs(String name) {
        NetworkCoordinator ref = NetworkCoordinatorHelper.narrow(orbAs(name).orb().string_to_object(coordinator));
        assertThat(ref._non_existent()).isFalse();
        useCertificate("operator");
        return ref;
    }

    /**
     * The nodes host crawler runs, asked on the coordinator's own connection ({@code nodes} needs no right): this JVM
     * presents one certificate at a time on new connections, so a test's callers are made one after the other and
     * never interleaved with another member's.
     */
    private List<String> crawlerNodes() {
        return List.of(deployment.host("crawler").nodes());
    }

    /** Host crawler as reached by the member {@code name}, on an ORB of its own. */
    private Host crawlerAs(String name) {
        return HostDirectory.connect(orbAs(name)).find("crawler").orElseThrow();
    }

    private OrbRuntime orbAs(String name) {
        useCertificate(name);
        OrbRuntime orb = OrbRuntime.start(OrbSettings.defaults().withNaming(naming).withCallTimeoutMillis(10_000));
        orbs.add(orb);
        return orb;
    }

    private void useCertificate(String name) {
        TransportSecurity.use(TlsIdentity.load(keys.resolve(name + ".p12")));
    }

    private String store(String name) {
        return keys.resolve(name + ".p12").toString();
    }
}
