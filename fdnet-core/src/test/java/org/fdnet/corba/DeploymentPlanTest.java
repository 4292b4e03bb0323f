package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Set;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;

class DeploymentPlanTest {
    private static NodeInfo data(String name, String host) {
        return new NodeInfo(NodeKind.DATA, name, host, "", "DoubleData", List.of());
    }

    private static NodeInfo relation(String name, String host) {
        return new NodeInfo(NodeKind.RELATION, name, host, "", "Copy", List.of());
    }

    private static NetworkInfo twoRobots() {
        NetworkInfo n = new NetworkInfo("two-robots");
        n.addNode("main", data("map", "flyer"));
        n.addNode("main", relation("survey", "flyer"));
        n.addNode("main", relation("plan", "crawler"));
        n.addNode("main", data("route", "crawler"));
        n.addNode("main", data("found", "localhost"));
        n.addConnection("main", ConnectionInfo.writer(new NodeRef("main", "survey"), new NodeRef("main", "map")));
        n.addConnection("main", ConnectionInfo.reader(new NodeRef("main", "map"), new NodeRef("main", "plan")));
        n.addConnection("main", ConnectionInfo.writer(new NodeRef("main", "plan"), new NodeRef("main", "route")));
        n.addConnection("main", ConnectionInfo.writer(new NodeRef("main", "plan"), new NodeRef("main", "found")));
        return n;
    }

    @Test
    void shouldPlaceEveryNodeOnTheHostItNamesAndLocalhostOnTheCoordinator() {
        DeploymentPlan plan = DeploymentPlan.of(twoRobots(), "run-1", Set.of());

        assertThat(plan.hosts()).containsExactly("flyer", "crawler", "run-1");
        assertThat(plan.shareOf("run-1").nodes()).extracting(p -> p.node().name()).containsExactly("found");
    }

    @Test
    void shouldKeepSameHostConnectionsDirectAndLinkCrossHostOnes() {
        DeploymentPlan plan = DeploymentPlan.of(twoRobots(), "run-1", Set.of());

        assertThat(plan.shareOf("flyer").standIns()).isEmpty();
        assertThat(plan.shareOf("crawler").standIns()).extracting(DeploymentPlan.StandIn::data)
                .containsExactly(new NodeRef("main", "map"), new NodeRef("main", "found"));
        assertThat(plan.links()).extracting(DeploymentPlan.Link::toString).containsExactly(
                "flyer:main/map -> crawler (link 1)",      // a Reader: from the Data's home
                "crawler:main/found -> run-1 (link 2)");   // a Writer: to the Data's home
    }

    @Test
    void shouldPlanAModuleNotLoadedAtStartOnlyWhenAsked() {
        NetworkInfo n = twoRobots();
        n.addModule("Search", false);
        n.addNode("Search", data("grid", "crawler"));

        assertThat(DeploymentPlan.of(n, "run-1", Set.of()).shareOf("crawler").nodes()).hasSize(2);
        assertThat(DeploymentPlan.of(n, "run-1", Set.of(), Set.of("Search")).shareOf("crawler").nodes())
                .extracting(p -> p.ref().toString()).contains("Search/grid");
    }

    @Test
    void shouldPlanNestedModulesAsTheirParentsLoadThem() {
        NetworkInfo n = twoRobots();
        n.addModule("Search", false);
        n.addModule("Search/Grid", true);
        n.addModule("Search/Grid/Fine", false);
        n.addNode("Search/Grid", data("cells", "crawler"));
        n.addNode("Search/Grid/Fine", data("subcells", "crawler"));

        assertThat(DeploymentPlan.of(n, "run-1", Set.of()).loaded()).doesNotContain("Search", "Search/Grid");
        assertThat(DeploymentPlan.of(n, "run-1", Set.of(), Set.of("Search")).loaded())
                .contains("Search", "Search/Grid").doesNotContain("Search/Grid/Fine");
        assertThat(DeploymentPlan.of(n, "run-1", Set.of(), Set.of("Search")).shareOf("crawler").nodes())
                .extracting(p -> p.ref().toString()).contains("Search/Grid/cells").doesNotContain("Search/Grid/Fine/subcells");
    }

    @Test
    void shouldTreatThisMachinesNamesAsLocal() {
        assertThat(DeploymentPlan.placeOf("Robot-PC", "run-1", Set.of("robot-pc"))).isEqualTo("run-1");
        assertThat(DeploymentPlan.placeOf("127.0.0.1", "run-1", Set.of())).isEqualTo("run-1");
        assertThat(DeploymentPlan.placeOf("flyer", "run-1", Set.of("robot-pc"))).isEqualTo("flyer");
    }
}
