package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

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
import org.fdnet.runtime.ChangeOutcome;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Structural changes of a running network over three processes (the test JVM coordinates as host "base"; child
 * JVMs run "flyer" and "crawler"), through {@link DistributedControl}: a module spanning two hosts is unloaded and
 * loaded again, and edits are applied on every host they touch (and stay applied when a host restarts) or refused
 * changing nothing.
 *
 * <pre>
 *   flyer: main/Source ══▶ crawler: Relay/Copy (in0) ══▶ base: Relay/Out          (module Relay: crawler + base)
 * </pre>
 */
@Timeout(value = 180, unit = TimeUnit.SECONDS)
class StructureChangesAcrossHostsTest {
    private static final NodeRef SOURCE = new NodeRef("main", "Source");
    private static final NodeRef COPY = new NodeRef("Relay", "Copy");
    private static final NodeRef OUT = new NodeRef("Relay", "Out");

    private CorbaCluster cluster;
    private Host flyer;
    private Host crawler;
    private RuntimeLocalNetwork base;
    private NetworkDeployment deployment;
    private DistributedControl control;

    @BeforeEach
    void deploy() throws Exception {
        cluster = CorbaCluster.start();
        flyer = cluster.startHost("flyer");
        crawler = cluster.startHost("crawler");
        base = LocalNetworks.forHost("base", List.of());
        HostProcess local = cluster.startLocalHost("base", base, LinkSettings.defaults());
        deployment = NetworkDeployment.start(DeploymentPlan.of(network(), "base", Set.of()), cluster.directory(),
                Map.of("base", local.reference()), DeploymentListener.quiet(), new MemoryEventSink(), 4, 10_000, 100);
        control = new DistributedControl(deployment);
        CoordinatorServant.publish(local.orb(), control); // as fdnet run does: the hosts' Servants see the whole network
    }

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
    void shouldUnloadAModuleSpanningTwoHostsWhileItRunsAndLoadItAgain() throws Exception {
        send(1);
        await(() -> Long.valueOf(1).equals(base.read(OUT)), () -> "Relay/Out on base: " + base.read(OUT));

        ChangeOutcome unloaded = control.unload("Relay");
        assertThat(unloaded.executed()).as(unloaded.toString()).isTrue();
        assertThat(unloaded.description()).contains("crawler").contains("base");
        assertThat(crawler.nodes()).doesNotContain(COPY.toString());
        assertThat(base.nodes()).doesNotContain(OUT);
        assertThat(deployment.plan().links()).isEmpty(); // nothing crosses hosts any more
        send(2);
        Thread.sleep(500);
        assertThat(base.read(OUT)).as("values stopped: Relay/Out does not run on base").isNull();
        assertThat(control.unload("Relay").reason()).contains("not loaded");

        ChangeOutcome loaded = control.load("Relay");
        assertThat(loaded.executed()).as(loaded.toString()).isTrue();
        assertThat(crawler.nodes()).contains(COPY.toString());
        send(3);
        await(() -> Long.valueOf(3).equals(base.read(OUT)), () -> "Relay/Out on base: " + base.read(OUT));
        assertThat(control.load("Relay").reason()).contains("already loaded");
        assertThat(control.unload("main").reason()).contains("always loaded");
        assertThat(deployment.brokenLinks()).isEmpty();
    }

    @Test
    void shouldApplyAnEditOnEveryHostItTouchesOrRefuseItChangingNothingAnywhere() throws Exception {
        NodeRef twice = new NodeRef("main", "Twice");
        NodeRef doubled = new NodeRef("main", "Doubled");
        ChangeOutcome added = control.apply("add Twice", n -> {
            n.addNode("main", new NodeInfo(NodeKind.RELATION, "Twice", "crawler", "", "Expression",
                    List.of(Parameter.named("expression", "in0 * 2"))));
            n.addNode("main", new NodeInfo(NodeKind.DATA, "Doubled", "localhost", "", "LongData", List.of()));
            n.addConnection("main", ConnectionInfo.reader(SOURCE, twice));
            n.addConnection("main", ConnectionInfo.writer(twice, doubled));
        });
        assertThat(added.executed()).as(added.toString()).isTrue();
        send(5);
        await(() -> Long.valueOf(10).equals(base.read(doubled)), () -> "Doubled on base: " + base.read(doubled));
        assertThat(control.snapshot().node(twice).host()).isEqualTo("crawler");

        // the edit is part of the deployment now: a crawler killed and restarted gets Twice back with its links
        cluster.kill("crawler");
        crawler = cluster.restart("crawler");
        await(() -> deployment.lostHosts().isEmpty() && Arrays.asList(crawler.nodes()).contains(twice.toString()),
                () -> "lost " + deployment.lostHosts() + ", crawler runs " + nodes(crawler));
        send(6);
        await(() -> Long.valueOf(12).equals(base.read(doubled)), () -> "Doubled on base: " + base.read(doubled));

        // crawler refuses a class outside its allowed paths: the flyer's new Data is not made either
        ChangeOutcome refused = control.apply("add Intruder", n -> {
            NodeRef intruder = n.addNode("main", new NodeInfo(NodeKind.RELATION, "Intruder", "crawler",
                    "/nonexistent/classes", "org.example.Intruder", List.of()));
            n.addNode("main", new NodeInfo(NodeKind.DATA, "Loot", "flyer", "", "LongData", List.of()));
            n.addConnection("main", ConnectionInfo.reader(SOURCE, intruder));
            n.addConnection("main", ConnectionInfo.writer(intruder, new NodeRef("main", "Loot")));
        });
        assertThat(refused.executed()).isFalse();
        assertThat(refused.reason()).contains("host crawler refuses main/Intruder")
                .contains("outside this host's allowed paths").endsWith("nothing changed on any host");
        assertThat(Arrays.asList(flyer.nodes())).doesNotContain("main/Loot");
        assertThat(Arrays.asList(crawler.nodes())).doesNotContain("main/Intruder");
        assertThat(control.snapshot().node(new NodeRef("main", "Loot"))).isNull();

        // a class the crawler allows (a bare library name) but cannot make is refused at prepare, before any host changed
        ChangeOutcome unmakeable = control.apply("add Phantom", n -> {
            NodeRef phantom = n.addNode("main", new NodeInfo(NodeKind.RELATION, "Phantom", "crawler", "",
                    "NoSuchRelation", List.of()));
            n.addNode("main", new NodeInfo(NodeKind.DATA, "Echo", "flyer", "", "LongData", List.of()));
            n.addConnection("main", ConnectionInfo.reader(SOURCE, phantom));
            n.addConnection("main", ConnectionInfo.writer(phantom, new NodeRef("main", "Echo")));
        });
        assertThat(unmakeable.executed()).isFalse();
        assertThat(unmakeable.reason()).contains("host crawler").contains("NoSuchRelation")
                .endsWith("nothing changed on any host");
        assertThat(Arrays.asList(flyer.nodes())).doesNotContain("main/Echo");
        assertThat(Arrays.asList(crawler.nodes())).doesNotContain("main/Phantom");

        // an edit the definition itself refuses reaches no host
        ChangeOutcome invalid = control.apply("connect a ghost",
                n -> n.addConnection("main", ConnectionInfo.reader(new NodeRef("main", "Ghost"), twice)));
        assertThat(invalid.executed()).isFalse();
        assertThat(invalid.reason()).contains("Ghost").endsWith("nothing changed on any host");

        // removing the node stops its values; the rest runs on
        ChangeOutcome removed = control.apply("remove Twice", n -> n.deleteNode(twice));
        assertThat(removed.executed()).as(removed.toString()).isTrue();
        assertThat(Arrays.asList(crawler.nodes())).doesNotContain(twice.toString());
        send(7);
        await(() -> Long.valueOf(7).equals(base.read(OUT)), () -> "Relay/Out on base: " + base.read(OUT));
        assertThat(base.read(doubled)).as("Twice is gone: Doubled keeps its last value").isEqualTo(12L);
    }

    @Test
    void shouldLetARelationThatAnEditStartsReshapeTheNetworkWithoutDeadlock() throws Exception {
        // The new Organizer fires as soon as the crawler commits (on the thread of that commit, while the coordinator
        // waits for it): its Visitor and Paste ask the coordinator in the middle of the coordinator's own change.
        ChangeOutcome added = control.apply("add an Organizer and a Gyro", n -> {
            n.addNode("main", new NodeInfo(NodeKind.RELATION, "Organizer", "crawler", "", "AutoFilter",
                    List.of(Parameter.named("period", "100"), Parameter.named("alpha", "0.5"))));
            n.addNode("main", new NodeInfo(NodeKind.DATA, "Gyro", "flyer", "", "DoubleSensor", List.of()));
        });
        // had the Organizer's calls waited for the coordinator, the crawler's commit would have timed out (5 s calls)
        assertThat(added.executed()).as(added.toString()).isTrue();
        await(() -> Arrays.asList(flyer.nodes()).contains("main/Gyro filter"), () -> "flyer runs " + nodes(flyer)
                + "\nCRAWLER:\n" + String.join("\n", cluster.output("crawler")));
        // the flyer runs the filter once it committed; the coordinator's plan follows when every host has
        NodeRef filter = new NodeRef("main", "Gyro filter");
        await(() -> control.snapshot().node(filter) != null, () -> "the coordinator's definition has no " + filter);
        assertThat(control.snapshot().node(filter).host()).isEqualTo("flyer");
    }

    private static String nodes(Host host) {
        try {
            return Arrays.toString(host.nodes());
        } catch (RuntimeException e) {
            return e.toString();
        }
    }

    private void send(long value) throws Exception {
        flyer.write(IdlMapping.id(SOURCE), ValueCodec.encode(value));
    }

    private static NetworkInfo network() {
        NetworkInfo n = new NetworkInfo("relay");
        n.addNode("main", new NodeInfo(NodeKind.DATA, "Source", "flyer", "", "LongData", List.of()));
        n.addModule("Relay", true);
        n.addNode("Relay", new NodeInfo(NodeKind.RELATION, "Copy", "crawler", "", "Expression",
                List.of(Parameter.named("expression", "in0"))));
        n.addNode("Relay", new NodeInfo(NodeKind.DATA, "Out", "localhost", "", "LongData", List.of()));
        n.addConnection("Relay", ConnectionInfo.reader(SOURCE, COPY));
        n.addConnection("Relay", ConnectionInfo.writer(COPY, OUT));
        return n;
    }

    @FunctionalInterface
    private interface Condition {
        boolean holds() throws Exception;
    }

    private static void await(Condition condition, Supplier<String> state) throws Exception {
        long deadline = System.currentTimeMillis() + 30_000;
        while (!condition.holds()) {
            if (System.currentTimeMillis() > deadline) {
                throw new AssertionError("not within 30 s: " + state.get());
            }
            Thread.sleep(50);
        }
    }
}
