package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(value = 30, unit = TimeUnit.SECONDS)
class RuntimeLocalNetworkTest {
    private static final NodeRef MAP = new NodeRef("main", "map");
    private static final NodeRef PLAN = new NodeRef("main", "plan");
    private static final NodeRef ROUTE = new NodeRef("main", "route");

    private final RuntimeLocalNetwork crawler = LocalNetworks.forHost("crawler", List.of());

    @AfterEach
    void stop() {
        crawler.close();
    }

    @Test
    void shouldFeedALocalRelationFromAStandInAndTellWhereValuesCameFrom() throws Exception {
        crawler.createStandIn(MAP, new NodeInfo(NodeKind.DATA, "map", "flyer", "", "DoubleData", List.of()));
        crawler.load("main", List.of(
                        new NodeInfo(NodeKind.RELATION, "plan", "", "", "Expression",
                                List.of(Parameter.named("expression", "2 * in0"))),
                        new NodeInfo(NodeKind.DATA, "route", "", "", "DoubleData", List.of())),
                List.of(ConnectionInfo.reader(MAP, PLAN), ConnectionInfo.writer(PLAN, ROUTE)));
        List<String> origins = new CopyOnWriteArrayList<>();
        crawler.observe(MAP, (v, fromHost, origin) -> origins.add(fromHost));
        List<Object> routes = new CopyOnWriteArrayList<>();
        crawler.observe(ROUTE, (v, fromHost, origin) -> routes.add(v));

        assertThat(crawler.nodes()).contains(MAP, PLAN, ROUTE);
        crawler.inject(MAP, 21.0, "flyer", new ValueOrigin("flyer#1#3", 0));

        long deadline = System.currentTimeMillis() + 5_000;
        while (!routes.contains(42.0) && System.currentTimeMillis() < deadline) {
            Thread.sleep(10);
        }
        assertThat(routes).as("%s", crawler.runtime().controller().relationStates()).contains(42.0);
        assertThat(origins).containsExactly("flyer");
    }

    @Test
    void shouldGiveTheOriginOnlyToTheInjectedValueNotToWhatARelationWritesBecauseOfIt() throws Exception {
        crawler.createStandIn(MAP, new NodeInfo(NodeKind.DATA, "map", "flyer", "", "DoubleData", List.of()));
        crawler.load("main", List.of(
                        new NodeInfo(NodeKind.RELATION, "plan", "", "", "Expression",
                                List.of(Parameter.named("expression", "2 * in0"))),
                        new NodeInfo(NodeKind.DATA, "route", "", "", "DoubleData", List.of())),
                List.of(ConnectionInfo.reader(MAP, PLAN), ConnectionInfo.writer(PLAN, ROUTE)));
        ValueOrigin origin = new ValueOrigin("flyer#1#3", 7);
        List<String> mapArrivals = new CopyOnWriteArrayList<>();
        crawler.observe(MAP, (v, fromHost, o) -> mapArrivals.add(v + " from " + fromHost + " at " + o));
        List<String> routeArrivals = new CopyOnWriteArrayList<>();
        crawler.observe(ROUTE, (v, fromHost, o) -> routeArrivals.add(v + " from " + fromHost + " at " + o));

        crawler.inject(MAP, 21.0, "flyer", origin);

        long deadline = System.currentTimeMillis() + 5_000;
        while (routeArrivals.isEmpty() && System.currentTimeMillis() < deadline) {
            Thread.sleep(10);
        }
        assertThat(mapArrivals).containsExactly("21.0 from flyer at " + origin);
        assertThat(routeArrivals).containsExactly("42.0 from null at null");
    }
}
