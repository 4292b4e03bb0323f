package org.fdnet.corba;

import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.LinkageIterator;
import org.fdnet.runtime.NodeDescription;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Servants;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.library.DoubleData;

/**
 * A Relation that reports what its Servants show of the whole network, for {@code ServantsAcrossHostsTest}: it runs
 * on one host (loaded there from this test's class folder, an allowed path) and writes into its String output
 * {@code Seen} the running Datas with their hosts (Visitor), the nodes downstream of {@code from} (Iterator) and the
 * connections crossed (LinkageIterator). Once, it asks Paste for a Relation of a class from {@code /nonexistent}
 * on host {@code pasteHost}, with a new Data on its own host, and writes the outcome into {@code PasteAnswer} (it
 * asks again when the coordinator says to try again: the network changed under it, or another change was running).
 */
public class WholeNetworkProbe extends Relation {
    private NodeRef from;
    private String pasteHost;
    private boolean answered;

    @Override
    protected void init(NodeParameters p) {
        from = new NodeRef("main", p.string("from", "Wheel"));
        pasteHost = p.string("pasteHost", "crawler");
    }

    @Override
    protected void compute(RelationContext c) {
        Servants s = c.servants();
        if (s.reflect().describe(from) == null) {
            c.output("Seen", Value.of("no " + from + " yet")); // the host has not been told the coordinator yet
            return;
        }
        List<String> datas = new ArrayList<>();
        for (NodeDescription d : s.visitor().datas()) {
            datas.add(d.ref() + "@" + d.host());
        }
        List<String> links = new ArrayList<>();
        for (LinkageIterator.Linkage l : s.linkageIterator(from)) {
            links.add(l.connection() + (l.live() ? " live" : " dormant"));
        }
        c.output("Seen", Value.of("datas=" + datas + " iterator=" + s.iterator(from).toList() + " links=" + links));
        if (!answered) {
            NodeInfo intruder = new NodeInfo(org.fdnet.netinfo.NodeKind.RELATION, "Intruder", pasteHost,
                    "/nonexistent/fdnet-classes", "org.example.Intruder", List.of(Parameter.named("x", "1")));
            String here = s.reflect().describe(c.self()).host();
            NodeInfo out = NodeInfo.data("IntruderOut", DoubleData.class.getName()).withHost(here);
            ChangeOutcome o = s.paste().pasteRelation("main", intruder, List.of(out), List.of(from),
                    List.of(new NodeRef("main", "IntruderOut")));
            String text = o.executed() ? "executed: " + o.description() : "refused: " + o.reason();
            answered = !text.endsWith("(try again)"); // the network changed meanwhile, or another change ran
            c.output("PasteAnswer", Value.of(text));
        }
    }
}
