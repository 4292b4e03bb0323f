package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.runtime.TestNetworks.*;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.library.DoubleSensor;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class ServantsTest {

    /** Uses every servant once from inside compute and records what it saw. */
    public static class Explorer extends Relation {
        static final List<String> seen = new CopyOnWriteArrayList<>();

        @Override
        protected void compute(RelationContext c) {
            Servants s = c.servants();
            seen.add("datas=" + s.visitor().datas().size());
            NodeDescription reflected = s.reflect().describe(new NodeRef("main", "B"));
            seen.add("reflect=" + reflected.kind() + ":" + reflected.value().asDouble() + ":" + reflected.connections().size());
            seen.add("iterator=" + s.iterator(new NodeRef("main", "A")).toList());
            for (LinkageIterator.Linkage l : s.linkageIterator(new NodeRef("main", "A"))) {
                seen.add("link=" + l.connection() + (l.live() ? " live" : " dormant"));
            }
        }
    }

    @Test
    void shouldFindDescribeAndFollowTheNetworkFromInsideARelation() throws Exception {
        NetworkInfo n = new NetworkInfo("explore");
        n.addNode("main", data("A", "DoubleData", "initial=1"));
        n.addNode("main", data("B", "DoubleData", "initial=2"));
        n.addNode("main", data("Trigger", "DoubleData"));
        n.addNode("main", relation("Copy", "Expression", "expression=in0"));
        n.addNode("main", relation("Explore", Explorer.class.getName()));
        read(n, "main", "A", "Copy");
        write(n, "main", "Copy", "B");
        read(n, "main", "Trigger", "Explore");
        Explorer.seen.clear();
        try (RuntimeNetwork net = start(n, null)) {
            quiet(net);
            assertThat(Explorer.seen).contains("datas=3", "reflect=DATA:1.0:1",
                    "iterator=[main/Copy, main/B]", "link=Reader main/A -> main/Copy live", "link=Writer main/Copy -> main/B live");
        }
    }

    @Test
    void shouldGiveEveryNewSensorAFilterByItself() throws Exception {
        // self-organization: AutoFilter watches for DoubleSensors and wires a LowPass to each new one
        NetworkInfo n = new NetworkInfo("self-organizing");
        n.addNode("main", relation("Organizer", "AutoFilter", "period=20", "alpha=0.5"));
        MemoryEventSink sink = new MemoryEventSink();
        try (RuntimeNetwork net = start(n, sink)) {
            Controller c = net.controller();
            assertThat(c.apply("plug a wheel sensor", NetworkEdits.addNode("main", data("Wheel", "DoubleSensor"))).executed()).isTrue();
            // wait until the filter has taken the sensor's initial 0, or the first push would be its first input
            eventually("a filter for Wheel that has fired once", () -> c.value(ref("Wheel filtered")) != null
                    && c.relationState(ref("Wheel filter")) != null && c.relationState(ref("Wheel filter")).firings() >= 1);
            DoubleSensor wheel = net.dataInstance(ref("Wheel"), DoubleSensor.class);
            wheel.push(8.0);
            quiet(net);
            wheel.push(8.0);
            quiet(net);
            // the filter started on the sensor's initial 0, then y += 0.5 (x - y) twice: 4, then 6
            assertThat(c.value(ref("Wheel filtered")).asDouble()).isEqualTo(6.0);
            // the network built it itself, and said so: creates and connects name the Organizer as source
            int organizer = c.nodeId(ref("Organizer"));
            List<NetworkCommandEvent> byOrganizer = sink.events(NetworkCommandEvent.class).stream()
                    .filter(e -> e.sourceId() == organizer).toList();
            assertThat(byOrganizer).extracting(NetworkCommandEvent::command)
                    .contains(NetworkCommand.CREATE, NetworkCommand.CONNECT);
            assertThat(byOrganizer).allSatisfy(e -> assertThat(e.sourceType()).isEqualTo("proc"));
            // and the snapshot holds what it built
            NetworkInfo snapshot = c.snapshot();
            assertThat(snapshot.node(ref("Wheel filter")).kind()).isEqualTo(NodeKind.RELATION);
            assertThat(snapshot.connectionsOf(ref("Wheel filter"))).hasSize(2);
            // a second sensor gets its own filter; the first is not filtered twice
            c.apply("plug a gyro", NetworkEdits.addNode("main", data("Gyro", "DoubleSensor")));
            eventually("a filter for Gyro", () -> c.relationState(ref("Gyro filter")) != null);
            Thread.sleep(60);
            assertThat(c.snapshot().main().nodes()).hasSize(7);
        }
    }

    /** Connects itself to a declared-but-inactive Reader, then disconnects a Writer, through Paste. */
    public static class Rewirer extends Relation {
        @Override
        protected void compute(RelationContext c) {
            if (c.inputCount() == 1) {
                c.servants().paste().activate(ConnectionKind.READER, new NodeRef("main", "Late"), c.self());
            }
        }
    }

    @Test
    void shouldActivateADeclaredConnectionThroughPaste() throws Exception {
        NetworkInfo n = new NetworkInfo("activate");
        n.addNode("main", data("Start", "DoubleData"));
        n.addNode("main", data("Late", "DoubleData"));
        n.addNode("main", relation("Rewire", Rewirer.class.getName()));
        read(n, "main", "Start", "Rewire");
        n.addConnection("main", new org.fdnet.netinfo.ConnectionInfo(ConnectionKind.READER, null, ref("Late"),
                ref("Rewire"), false, false, false));
        try (RuntimeNetwork net = start(n, null)) {
            eventually("the Late reader is live", () -> net.controller().snapshot().connectionsOf(ref("Late")).get(0)
                    .connection().exists());
            quiet(net);
            assertThat(net.controller().relationState(ref("Rewire")).status()).isEqualTo(RelationStatus.RUNNING);
        }
    }
}
