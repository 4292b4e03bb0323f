package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.fdnet.corba.idl.Host;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Servants see and reshape the whole network over three processes: the test JVM coordinates (host "base"), child
 * JVMs run "flyer" and "crawler".
 *
 * <pre>
 *   flyer:   Organizer (AutoFilter) ──Visitor──▶ finds the DoubleSensor Wheel on crawler
 *                                   ──Paste───▶ crawler: Wheel ──Reader──▶ Wheel filter (LowPass) ──Writer──▶ Wheel filtered
 *   flyer:   Probe ──Visitor/Iterator/LinkageIterator──▶ Seen (what it saw, on every host)
 *                  ──Paste: Intruder (class outside crawler's allowed paths) + IntruderOut on flyer──▶ refused
 * </pre>
 */
@Timeout(value = 180, unit = TimeUnit.SECONDS)
class ServantsAcrossHostsTest {
    private static final NodeRef WHEEL = new NodeRef("main", "Wheel");
    private static final NodeRef FILTER = new NodeRef("main", "Wheel filter");
    private static final NodeRef FILTERED = new NodeRef("main", "Wheel filtered");
    private static final NodeRef SEEN = new NodeRef("main", "Seen");
    private static final NodeRef PASTE_ANSWER = new NodeRef("main", "PasteAnswer");

    private CorbaCluster cluster;
    private NetworkDeployment deployment;

    @AfterEach
    void stop() {
        if (deployment != null) {
            deployment.close();
        }
        if (cluster != null) {
            cluster.close();
        }
    }

    @Test
    void shouldLetARelationOnOneHostSeeTheWholeNetworkAndBuildAFilterOnAnotherHostThatValuesFlowThrough()
            throws Exception {
        cluster = CorbaCluster.start();
        Path testClasses = Path.of(WholeNetworkProbe.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        Host flyer = cluster.startHost("flyer", "--allow-path", testClasses.toString());
        Host crawler = cluster.startHost("crawler");
        HostProcess base = cluster.startLocalHost("base", LocalNetworks.forHost("base", List.of()), LinkSettings.defaults());
        DeploymentPlan plan = DeploymentPlan.of(network(testClasses), "base", Set.of());
        deployment = NetworkDeployment.start(plan, cluster.directory(), Map.of("base", base.reference()),
                DeploymentListener.quiet(), new MemoryEventSink(), 4, 10_000, 100);
        DistributedControl control = new DistributedControl(deployment);
        CoordinatorServant.publish(base.orb(), control);

        // The Organizer on the flyer saw the crawler's sensor and built its filter there, connected to it.
        await(() -> Arrays.asList(crawler.nodes()).contains(FILTER.toString()), () -> "crawler runs "
                + Arrays.toString(crawler.nodes()) + "\nFLYER:\n" + String.join("\n", cluster.output("flyer")));
        assertThat(crawler.nodes()).contains(FILTERED.toString());
        assertThat(flyer.nodes()).doesNotContain(FILTER.toString(), FILTERED.toString());
        // the crawler runs them once it committed; the coordinator's plan follows when every host has
        await(() -> control.snapshot().node(FILTER) != null, () -> "the coordinator's definition has no " + FILTER);
        NetworkInfo running = control.snapshot();
        assertThat(running.node(FILTER).host()).isEqualTo("crawler");
        assertThat(running.connectionsOf(FILTER)).extracting(c -> c.connection().toString())
                .contains(ConnectionInfo.reader(WHEEL, FILTER).toString(), ConnectionInfo.writer(FILTER, FILTERED).toString());

        // Values flow through the new node: the sensor's 8s reach the filtered Data (alpha 0.5: 4, 6, 7, 7.5, ...).
        await(() -> {
            crawler.write(IdlMapping.id(WHEEL), ValueCodec.encode(8.0));
            return read(crawler, FILTERED) instanceof Double d && d > 7.0 && d <= 8.0;
        }, () -> "Wheel filtered on crawler: " + read(crawler, FILTERED));

        // The Probe on the flyer walked the whole network: the crawler's Datas, the filter downstream of Wheel.
        await(() -> String.valueOf(read(flyer, SEEN)).contains("main/Wheel filter"), () -> "Seen: " + read(flyer, SEEN));
        String seen = (String) read(flyer, SEEN);
        assertThat(seen).contains("main/Wheel@crawler", "main/Seen@flyer", "main/Wheel filtered@crawler")
                .contains("iterator=[main/Wheel filter, main/Wheel filtered]")
                .contains("Reader main/Wheel -> main/Wheel filter live");

        // Its paste of a class the crawler does not allow was refused, and changed nothing on any host.
        await(() -> String.valueOf(read(flyer, PASTE_ANSWER)).startsWith("refused: "),
                () -> "PasteAnswer: " + read(flyer, PASTE_ANSWER));
        assertThat((String) read(flyer, PASTE_ANSWER)).contains("host crawler refuses main/Intruder")
                .contains("outside this host's allowed paths").contains("nothing changed on any host");
        assertThat(crawler.nodes()).doesNotContain("main/Intruder", "main/IntruderOut");
        assertThat(flyer.nodes()).doesNotContain("main/Intruder", "main/IntruderOut");
        assertThat(control.snapshot().node(new NodeRef("main", "Intruder"))).isNull();
        assertThat(control.snapshot().node(new NodeRef("main", "IntruderOut"))).isNull();
        assertThat(deployment.brokenLinks()).isEmpty();
    }

    private static NetworkInfo network(Path testClasses) {
        NetworkInfo n = new NetworkInfo("servants-across-hosts");
        n.addNode("main", new NodeInfo(NodeKind.RELATION, "Organizer", "flyer", "", "AutoFilter",
                List.of(Parameter.named("period", "100"), Parameter.named("alpha", "0.5"))));
        n.addNode("main", new NodeInfo(NodeKind.DATA, "Wheel", "crawler", "", "DoubleSensor", List.of()));
        NodeRef probe = n.addNode("main", new NodeInfo(NodeKind.RELATION, "Probe", "flyer", testClasses.toString(),
                WholeNetworkProbe.class.getName(), List.of(Parameter.named("period", "100"))));
        n.addNode("main", new NodeInfo(NodeKind.DATA, "Seen", "flyer", "", "StringData", List.of()));
        n.addNode("main", new NodeInfo(NodeKind.DATA, "PasteAnswer", "flyer", "", "StringData", List.of()));
        n.addNode("main", new NodeInfo(NodeKind.DATA, "Here", "localhost", "", "DoubleData", List.of()));
        n.addConnection("main", ConnectionInfo.writer(probe, SEEN));
        n.addConnection("main", ConnectionInfo.writer(probe, PASTE_ANSWER));
        return n;
    }

    private static Object read(Host host, NodeRef data) {
        try {
            return ValueCodec.decode(host.read(IdlMapping.id(data)));
        } catch (Exception e) {
            return e.toString();
        }
    }

    @FunctionalInterface
    private interface Condition {
        boolean holds() throws Exception;
    }

    private static void await(Condition condition, Supplier<String> state) throws Exception {
        long deadline = System.currentTimeMillis() + 40_000;
        while (!condition.holds()) {
            if (System.currentTimeMillis() > deadline) {
                throw new AssertionError("not within 40 s: " + state.get());
            }
            Thread.sleep(100);
        }
    }
}
