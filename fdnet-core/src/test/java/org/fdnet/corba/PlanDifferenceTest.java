package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Set;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.junit.jupiter.api.Test;

class PlanDifferenceTest {
    private static final NodeRef MAP = new NodeRef("main", "map");
    private static final NodeRef PLAN = new NodeRef("main", "plan");
    private static final NodeRef ROUTE = new NodeRef("main", "route");

    private static NetworkInfo network() {
        NetworkInfo n = new NetworkInfo("n");
        n.addNode("main", new NodeInfo(NodeKind.DATA, "map", "flyer", "", "DoubleData", List.of()));
        n.addNode("main", new NodeInfo(NodeKind.RELATION, "plan", "crawler", "", "Expression",
                List.of(Parameter.named("expression", "in0"))));
        n.addNode("main", new NodeInfo(NodeKind.DATA, "route", "crawler", "", "DoubleData", List.of()));
        n.addConnection("main", ConnectionInfo.reader(MAP, PLAN));
        n.addConnection("main", ConnectionInfo.writer(PLAN, ROUTE));
        return n;
    }

    @Test
    void shouldGiveANewNodeOnAnotherHostItsStandInAndANewLinkKeepingTheOldLinksIds() {
        DeploymentPlan before = DeploymentPlan.of(network(), "run", Set.of());
        NetworkInfo next = before.definition();
        NodeRef show = next.addNode("main", new NodeInfo(NodeKind.RELATION, "show", "flyer", "", "Print", List.of()));
        next.addConnection("main", ConnectionInfo.reader(ROUTE, show));
        DeploymentPlan after = before.next(next, before.loaded());

        PlanDifference d = PlanDifference.between(before, after);

        assertThat(d.hosts()).containsOnlyKeys("flyer");
        PlanDifference.HostChange flyer = d.hosts().get("flyer");
        assertThat(flyer.create()).extracting(DeploymentPlan.Placed::ref).containsExactly(show);
        assertThat(flyer.standIns()).extracting(DeploymentPlan.StandIn::data).containsExactly(ROUTE);
        assertThat(flyer.connect()).extracting(c -> c.connection().relation()).containsExactly(show);
        assertThat(d.closed()).isEmpty();
        assertThat(d.opened()).extracting(DeploymentPlan.Link::toString).containsExactly("crawler:main/route -> flyer (link 2)");
        assertThat(after.links()).extracting(DeploymentPlan.Link::toString).contains("flyer:main/map -> crawler (link 1)");
    }

    @Test
    void shouldRecreateAChangedNodeWithItsConnectionsAndRelinkAStandInNeverReusingALinkId() {
        DeploymentPlan before = DeploymentPlan.of(network(), "run", Set.of());
        NetworkInfo changed = before.definition();
        changed.updateNode(MAP, changed.node(MAP).withParameters(List.of(Parameter.named("initial", "3"))));
        DeploymentPlan after = before.next(changed, before.loaded());

        PlanDifference d = PlanDifference.between(before, after);

        assertThat(d.hosts().get("flyer").destroy()).containsExactly(MAP);
        assertThat(d.hosts().get("flyer").create()).extracting(DeploymentPlan.Placed::ref).containsExactly(MAP);
        // the crawler's stand-in carries the Data's definition: it is made again, with its Reader
        assertThat(d.hosts().get("crawler").destroy()).containsExactly(MAP);
        assertThat(d.hosts().get("crawler").connect()).extracting(c -> c.connection().data()).containsExactly(MAP);
        assertThat(d.closed()).extracting(DeploymentPlan.Link::id).containsExactly(1L);
        assertThat(d.opened()).extracting(DeploymentPlan.Link::id).containsExactly(1L);

        // unloading everything but main, then a new link: ids only grow
        NetworkInfo without = after.definition();
        without.deleteNode(PLAN);
        DeploymentPlan cut = after.next(without, after.loaded());
        assertThat(PlanDifference.between(after, cut).closed()).extracting(DeploymentPlan.Link::id).containsExactly(1L);
        NetworkInfo again = cut.definition();
        again.addNode("main", new NodeInfo(NodeKind.RELATION, "plan", "crawler", "", "Expression",
                List.of(Parameter.named("expression", "in0"))));
        again.addConnection("main", ConnectionInfo.reader(MAP, PLAN));
        assertThat(cut.next(again, cut.loaded()).links()).extracting(DeploymentPlan.Link::id).containsExactly(2L);
    }
}
