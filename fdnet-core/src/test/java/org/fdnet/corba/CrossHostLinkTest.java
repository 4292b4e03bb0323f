package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.stream.LongStream;
import org.fdnet.corba.idl.ConnectionSpec;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.HostHelper;
import org.fdnet.corba.idl.NodeSpec;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.Parameter;
import org.fdnet.corba.idl.Refused;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Links between real host processes: a naming service and hosts as child JVMs on 127.0.0.1, an observing
 * host in the test JVM.
 *
 * <pre>
 *   base (test JVM) main/map ──link 1──▶ crawler (child) stand-in main/map ──link 2──▶ observer (test JVM) main/seen
 * </pre>
 */
@Timeout(value = 150, unit = TimeUnit.SECONDS)
class CrossHostLinkTest {
    private static final NodeRef MAP = new NodeRef("main", "map");
    private static final NodeRef SEEN = new NodeRef("main", "seen");

    private CorbaCluster cluster;
    private DataOnlyNetwork baseNetwork;
    private HostProcess base;
    private HostProcess observer;
    private final List<Long> received = new ArrayList<>();

    @BeforeEach
    void startCluster() {
        cluster = CorbaCluster.start();
        baseNetwork = new DataOnlyNetwork();
        DataOnlyNetwork observerNetwork = new DataOnlyNetwork();
        LinkSettings small = new LinkSettings(4, 256, 1 << 16, 100);
        base = cluster.startLocalHost("base", baseNetwork, small);
        observer = cluster.startLocalHost("observer", observerNetwork, small);
        baseNetwork.create(MAP, NodeInfo.data(MAP.node(), "LongData"));
        observerNetwork.create(SEEN, NodeInfo.data(SEEN.node(), "LongData"));
        observerNetwork.observe(SEEN, (value, fromHost, origin) -> {
            synchronized (received) {
                received.add((Long) value);
            }
        });
    }

    @AfterEach
    void stopCluster() {
        cluster.close();
    }

    @Test
    void shouldDeliverEveryValueInOrderAcrossProcesses() throws Exception {
        wireThrough(cluster.startHost("crawler"));

        int n = 50_000;
        for (long i = 0; i < n; i++) {
            baseNetwork.write(MAP, i);
        }

        awaitTrue(() -> receivedCount() >= n, 30_000);
        assertThat(snapshot()).containsExactlyElementsOf(LongStream.range(0, n).boxed().toList());
    }

    @Test
    void shouldLoseNoValueWrittenAfterAKilledHostIsRewired() throws Exception {
        wireThrough(cluster.startHost("crawler"));
        long next = 0;
        for (; next < 20_000; next++) {
            baseNetwork.write(MAP, next);
        }
        cluster.kill("crawler");
        long killedAt = next;
        for (; next < 30_000; next++) { // while the crawler is dead: kept by link 1
            baseNetwork.write(MAP, next);
        }
        awaitTrue(() -> base.servant().outboundLinks().get(0).broken(), 10_000);

        wireThrough(cluster.restart("crawler"));
        for (; next < 40_000; next++) {
            baseNetwork.write(MAP, next);
        }
        long last = next - 1;

        awaitTrue(() -> lastSeen() == last, 30_000);
        List<Long> got = snapshot();
        assertThat(got).isSorted().doesNotHaveDuplicates();
        assertThat(got.stream().filter(v -> v >= killedAt).toList())
                .containsExactlyElementsOf(LongStream.range(killedAt, next).boxed().toList());
        assertThat(base.servant().outboundLinks().get(0).lost()).isZero();
    }

    @Test
    void shouldRefuseARemoteCreateOutsideTheAllowedPathsOrBuiltIns() throws Exception {
        Host crawler = cluster.startHost("crawler", "--allow-path", System.getProperty("java.io.tmpdir"));
        NodeInfo outside = new NodeInfo(org.fdnet.netinfo.NodeKind.RELATION, "evil", "crawler", "/etc",
                "Evil", List.of());

        assertThatThrownBy(() -> crawler.createNode(IdlMapping.spec("main", outside)))
                .isInstanceOf(Refused.class)
                .satisfies(e -> assertThat(((Refused) e).reason).contains("outside this host's allowed paths"));
        assertThat(crawler.nodes()).isEmpty();
        assertThatThrownBy(() -> crawler.createNode(IdlMapping.spec("main",
                new NodeInfo(org.fdnet.netinfo.NodeKind.RELATION, "evil", "crawler", "", "java.lang.Thread", List.of()))))
                .isInstanceOf(Refused.class)
                .satisfies(e -> assertThat(((Refused) e).reason).contains("is not built in"));
    }

    @Test
    void shouldRefuseABatchClaimingMoreValuesThanItHoldsAndKeepServing() {
        // The request comes through another ORB, over IIOP: the host reads it as a peer's request.
        org.omg.CORBA.portable.ObjectImpl peer = (org.omg.CORBA.portable.ObjectImpl) base.orb().orb()
                .string_to_object(observer.orb().orb().object_to_string(observer.reference()));
        org.omg.CORBA.portable.OutputStream hostile = peer._request("deliver", true);
        hostile.write_longlong(2);
        hostile.write_longlong(0);
        hostile.write_string("base/1/1");
        hostile.write_longlong(0);
        hostile.write_long(Integer.MAX_VALUE); // the values' count, as the request's last bytes: nothing follows

        assertThatThrownBy(() -> peer._invoke(hostile)).isInstanceOf(org.omg.CORBA.MARSHAL.class);
        assertThat(HostHelper.narrow(peer).name()).isEqualTo("observer");
    }

    /**
     * The wiring the coordinator makes for a host (again after a restart): the crawler's Relation "use"
     * reads the map, so the crawler keeps a stand-in of it.
     */
    private void wireThrough(Host crawler) throws Exception {
        crawler.createStandIn(IdlMapping.spec("main", NodeInfo.data(MAP.node(), "LongData")), "base");
        NodeRef use = new NodeRef("main", "use");
        NodeRef out = new NodeRef("main", "out");
        crawler.loadModule("main", new NodeSpec[] {
            IdlMapping.spec("main", NodeInfo.relation(use.node(), "Expression", Parameter.named("expression", "in0"))),
            IdlMapping.spec("main", NodeInfo.data(out.node(), "LongData"))}, new ConnectionSpec[] {
                IdlMapping.spec(ConnectionInfo.reader(MAP, use)), IdlMapping.spec(ConnectionInfo.writer(use, out))});
        crawler.acceptLink(1, IdlMapping.id(MAP), "base");
        base.reference().forward(1, IdlMapping.id(MAP), crawler, "crawler", 4);
        observer.reference().acceptLink(2, IdlMapping.id(SEEN), "crawler");
        crawler.forward(2, IdlMapping.id(MAP), observer.reference(), "observer", 4);
    }

    /** The last value seen, or -1 before the first. */
    private long lastSeen() {
        List<Long> got = snapshot();
        return got.isEmpty() ? -1 : got.get(got.size() - 1);
    }

    private int receivedCount() {
        synchronized (received) {
            return received.size();
        }
    }

    private List<Long> snapshot() {
        synchronized (received) {
            return List.copyOf(received);
        }
    }

    private static void awaitTrue(BooleanSupplier condition, long millis) throws InterruptedException {
        long deadline = System.currentTimeMillis() + millis;
        while (!condition.getAsBoolean()) {
            if (System.currentTimeMillis() > deadline) {
                throw new AssertionError("condition not met within " + millis + " ms");
            }
            Thread.sleep(20);
        }
    }
}
