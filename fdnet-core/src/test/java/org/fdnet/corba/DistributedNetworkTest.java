package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.stream.LongStream;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
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
 * A network over three hosts — a naming service, "flyer" and "crawler" as child JVMs, and "base" in the
 * test JVM — deployed by {@link NetworkDeployment} as {@code fdnet run} does it.
 *
 * <pre>
 *   flyer:  Count (every 20 ms: Log + 1) ──Writer──▶ stand-in Log ══link══▶ crawler: Data Log
 *   crawler: Data Log ══link══▶ base: stand-in Log ──Reader──▶ Watch ──Writer──▶ Data Seen
 * </pre>
 *
 * Every value of the counter crosses two hosts as a value (no Relation in between may coalesce it), so
 * the test can check each one at base.
 */
@Timeout(value = 150, unit = TimeUnit.SECONDS)
class DistributedNetworkTest {
    private static final NodeRef LOG = new NodeRef("main", "Log");

    private CorbaCluster cluster;
    private RuntimeLocalNetwork baseNetwork;
    private NetworkDeployment deployment;
    private final List<Long> seen = new ArrayList<>();

    @BeforeEach
    void startHosts() throws Exception {
        cluster = CorbaCluster.start();
        cluster.startHost("flyer");
        cluster.startHost("crawler");
        baseNetwork = LocalNetworks.forHost("base", List.of());
        HostProcess base = cluster.startLocalHost("base", baseNetwork, LinkSettings.defaults());
        DeploymentPlan plan = DeploymentPlan.of(counterNetwork(), "base", Set.of());
        MemoryEventSink events = new MemoryEventSink();
        deployment = NetworkDeployment.start(plan, cluster.directory(), Map.of("base", base.reference()),
                DeploymentListener.quiet(), events, 4, 10_000, 100);
        baseNetwork.observe(LOG, (value, fromHost, origin) -> {
            synchronized (seen) {
                seen.add((Long) value);
            }
        });
        this.events = events;
    }

    private MemoryEventSink events;

    @AfterEach
    void stop() {
        if (deployment != null) {
            deployment.close();
        }
        cluster.close();
    }

    @Test
    void shouldDeliverEveryValueInOrderAcrossThreeHosts() throws Exception {
        awaitTrue(() -> count() >= 150, 30_000, () -> "values seen at base: " + snapshot() + " flyer Log "
                + read("flyer") + " crawler Log " + read("crawler") + " base " + baseNetwork.runtime().controller().relationStates()
                + baseNetwork.runtime().controller().remoteLinks() + "\nFLYER:\n" + String.join("\n", cluster.output("flyer")) + "\nCRAWLER:\n" + String.join("\n", cluster.output("crawler")));

        List<Long> got = snapshot();
        long first = got.get(0);
        assertThat(got).containsExactlyElementsOf(LongStream.range(first, first + got.size()).boxed().toList());
    }

    @Test
    void shouldRewireAKilledHostAndLoseNoValueWrittenAfterItsDeath() throws Exception {
        awaitTrue(() -> count() >= 50, 30_000);
        cluster.kill("crawler");
        long producedBeforeDeath = (Long) ValueCodec.decode(deployment.host("flyer").read(IdlMapping.id(LOG)));

        awaitTrue(() -> deployment.lostHosts().contains("crawler"), 10_000);
        assertThat(deployment.brokenLinks()).hasSize(3); // both ways between flyer and crawler, crawler to base
        long countAtDeath = count();
        Thread.sleep(500); // flyer runs on; what it writes for the crawler waits in its link
        assertThat(count()).isEqualTo(countAtDeath);

        cluster.restart("crawler");
        awaitTrue(() -> deployment.lostHosts().isEmpty() && deployment.brokenLinks().isEmpty(), 20_000);
        long producedAfterRecovery = (Long) ValueCodec.decode(deployment.host("flyer").read(IdlMapping.id(LOG)));
        awaitTrue(() -> lastSeen() >= producedAfterRecovery + 50,
                30_000);

        List<Long> got = snapshot();
        long last = got.get(got.size() - 1);
        // Never twice, never out of order: values the dead crawler had passed on and the flyer sends again
        // are recognised by their origin and skipped.
        assertThat(got).isSorted().doesNotHaveDuplicates();
        // Every value produced after the crawler died arrives.
        assertThat(got.stream().filter(v -> v > producedBeforeDeath).toList())
                .containsExactlyElementsOf(LongStream.rangeClosed(producedBeforeDeath + 1, last).boxed().toList());
        assertThat(deployment.recoveryMillis()).containsKey("crawler");
        assertThat(events.events()).filteredOn(e -> e instanceof NetworkCommandEvent c
                && c.command() == NetworkCommand.DISCONNECT && c.paramsType().equals("link")).hasSize(3);
    }

    private static NetworkInfo counterNetwork() {
        NetworkInfo n = new NetworkInfo("counter");
        n.addNode("main", new NodeInfo(NodeKind.DATA, "Log", "crawler", "", "LongData", List.of()));
        n.addNode("main", new NodeInfo(NodeKind.RELATION, "Count", "flyer", "", "Expression",
                List.of(Parameter.named("expression", "in0 + 1"), Parameter.named("period", "20"))));
        n.addNode("main", new NodeInfo(NodeKind.RELATION, "Watch", "localhost", "", "Expression",
                List.of(Parameter.named("expression", "in0"))));
        n.addNode("main", new NodeInfo(NodeKind.DATA, "Seen", "localhost", "", "LongData", List.of()));
        NodeRef count = new NodeRef("main", "Count");
        NodeRef watch = new NodeRef("main", "Watch");
        n.addConnection("main", ConnectionInfo.reader(LOG, count));
        n.addConnection("main", ConnectionInfo.writer(count, LOG));
        n.addConnection("main", ConnectionInfo.reader(LOG, watch));
        n.addConnection("main", ConnectionInfo.writer(watch, new NodeRef("main", "Seen")));
        return n;
    }

    private String read(String host) {
        try {
            return String.valueOf(ValueCodec.decode(deployment.host(host).read(IdlMapping.id(LOG))));
        } catch (Exception e) {
            return e.toString();
        }
    }

    /** The last value seen, or -1 before the first. */
    private long lastSeen() {
        List<Long> got = snapshot();
        return got.isEmpty() ? -1 : got.get(got.size() - 1);
    }

    private int count() {
        synchronized (seen) {
            return seen.size();
        }
    }

    private List<Long> snapshot() {
        synchronized (seen) {
            return List.copyOf(seen);
        }
    }

    private static void awaitTrue(BooleanSupplier condition, long millis) throws InterruptedException {
        awaitTrue(condition, millis, () -> "");
    }

    private static void awaitTrue(BooleanSupplier condition, long millis, java.util.function.Supplier<String> state)
            throws InterruptedException {
        long deadline = System.currentTimeMillis() + millis;
        while (!condition.getAsBoolean()) {
            if (System.currentTimeMillis() > deadline) {
                throw new AssertionError("condition not met within " + millis + " ms " + state.get());
            }
            Thread.sleep(20);
        }
    }
}
