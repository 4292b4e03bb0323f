package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The basic loop of a distributed robot: a sensor on one host, its controller on another, the actuator
 * back on the first. "base" runs in the test JVM, "crawler" is a child JVM.
 *
 * <pre>
 *   base: Data Sensor ══link══▶ crawler: stand-in Sensor ──Reader──▶ Control (in0 * 10) ──Writer──▶ Data Command
 *   crawler: Data Command ══link══▶ base: stand-in Command ──Reader──▶ Actuate (in0) ──Writer──▶ Data Actuated
 * </pre>
 *
 * Control fires because of a value that came from base, on the thread that injected it; what it writes is
 * a new value of the crawler's, not an echo of base's, so it must go back to base.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class RoundTripAcrossHostsTest {
    private static final NodeRef SENSOR = new NodeRef("main", "Sensor");
    private static final NodeRef COMMAND = new NodeRef("main", "Command");
    private static final NodeRef ACTUATED = new NodeRef("main", "Actuated");

    private CorbaCluster cluster;
    private RuntimeLocalNetwork baseNetwork;
    private NetworkDeployment deployment;

    @BeforeEach
    void startHosts() throws Exception {
        cluster = CorbaCluster.start();
        cluster.startHost("crawler");
        baseNetwork = LocalNetworks.forHost("base", List.of());
        HostProcess base = cluster.startLocalHost("base", baseNetwork, LinkSettings.defaults());
        DeploymentPlan plan = DeploymentPlan.of(loopNetwork(), "base", Set.of());
        deployment = NetworkDeployment.start(plan, cluster.directory(), Map.of("base", base.reference()),
                DeploymentListener.quiet(), new MemoryEventSink(), 4, 10_000, 100);
    }

    @AfterEach
    void stop() {
        if (deployment != null) {
            deployment.close();
        }
        cluster.close();
    }

    @Test
    void shouldSendAnOutputComputedFromARemoteValueBackToTheHostTheValueCameFrom() throws Exception {
        for (long reading = 1; reading <= 3; reading++) {
            baseNetwork.write(SENSOR, reading);
            long expected = reading * 10;
            awaitTrue(() -> Long.valueOf(expected).equals(baseNetwork.read(ACTUATED)), 20_000,
                    () -> "base Command " + baseNetwork.read(COMMAND) + ", Actuated " + baseNetwork.read(ACTUATED)
                            + ", crawler Command " + read("crawler", COMMAND) + "\nCRAWLER:\n"
                            + String.join("\n", cluster.output("crawler")));
        }
        assertThat(deployment.brokenLinks()).isEmpty();
    }

    private static NetworkInfo loopNetwork() {
        NetworkInfo n = new NetworkInfo("loop");
        n.addNode("main", new NodeInfo(NodeKind.DATA, "Sensor", "localhost", "", "LongData", List.of()));
        n.addNode("main", new NodeInfo(NodeKind.RELATION, "Control", "crawler", "", "Expression",
                List.of(Parameter.named("expression", "in0 * 10"))));
        n.addNode("main", new NodeInfo(NodeKind.DATA, "Command", "crawler", "", "LongData", List.of()));
        n.addNode("main", new NodeInfo(NodeKind.RELATION, "Actuate", "localhost", "", "Expression",
                List.of(Parameter.named("expression", "in0"))));
        n.addNode("main", new NodeInfo(NodeKind.DATA, "Actuated", "localhost", "", "LongData", List.of()));
        NodeRef control = new NodeRef("main", "Control");
        NodeRef actuate = new NodeRef("main", "Actuate");
        n.addConnection("main", ConnectionInfo.reader(SENSOR, control));
        n.addConnection("main", ConnectionInfo.writer(control, COMMAND));
        n.addConnection("main", ConnectionInfo.reader(COMMAND, actuate));
        n.addConnection("main", ConnectionInfo.writer(actuate, ACTUATED));
        return n;
    }

    private String read(String host, NodeRef data) {
        try {
            return String.valueOf(ValueCodec.decode(deployment.host(host).read(IdlMapping.id(data))));
        } catch (Exception e) {
            return e.toString();
        }
    }

    private static void awaitTrue(BooleanSupplier condition, long millis, Supplier<String> state)
            throws InterruptedException {
        long deadline = System.currentTimeMillis() + millis;
        while (!condition.getAsBoolean()) {
            if (System.currentTimeMillis() > deadline) {
                throw new AssertionError("condition not met within " + millis + " ms: " + state.get());
            }
            Thread.sleep(20);
        }
    }
}
