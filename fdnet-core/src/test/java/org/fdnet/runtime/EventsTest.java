package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.runtime.TestNetworks.*;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class EventsTest {

    private static NetworkInfo network() {
        NetworkInfo n = new NetworkInfo("events");
        n.addNode("main", data("A", "DoubleData"));
        n.addNode("main", data("B", "DoubleData"));
        n.addNode("main", relation("Fast", "PeriodicSource", "period=1"));
        n.addNode("main", relation("Copy", "Expression", "expression=in0"));
        write(n, "main", "Fast", "A");
        read(n, "main", "A", "Copy");
        write(n, "main", "Copy", "B");
        n.addModule("Extra", true);
        n.addNode("Extra", data("C", "DoubleData"));
        n.addNode("Extra", relation("Echo", "Expression", "expression=in0"));
        read(n, "Extra", "A", "Echo");
        write(n, "Extra", "Echo", "C");
        return n;
    }

    @Test
    void shouldStampEveryEventOfASourceWithAUniqueStrictlyIncreasingTime() throws Exception {
        MemoryEventSink sink = new MemoryEventSink();
        try (RuntimeNetwork net = start(network(), sink)) {
            for (int i = 0; i < 2000; i++) {
                net.controller().setValue(ref("A"), Value.of((double) i));
            }
            net.controller().unload("Extra");
            net.controller().load("Extra");
            Thread.sleep(100);
        }
        Map<Integer, Long> last = new HashMap<>();
        Set<String> keys = new HashSet<>();
        for (NetworkEvent e : sink.events()) {
            assertThat(keys.add(e.sourceId() + "@" + e.time())).as("unique (sourceid, time) " + e).isTrue();
        }
        // per source, in the order a single writer produced them: Data values are produced under one lock
        for (DataValueEvent e : sink.events(DataValueEvent.class)) {
            Long previous = last.put(e.sourceId(), e.time());
            if (previous != null) {
                assertThat(e.time()).as("time of %s after %d", e, previous).isGreaterThan(previous);
            }
        }
        assertThat(sink.events(DataValueEvent.class).size()).isGreaterThan(2000);
    }

    @Test
    void shouldNameEveryNodeBeforeItsOtherEventsAndLogEveryStructuralCommand() throws Exception {
        MemoryEventSink sink = new MemoryEventSink();
        try (RuntimeNetwork net = start(network(), sink)) {
            net.controller().unload("Extra");
            net.controller().apply("add D", NetworkEdits.addNode("main", data("D", "LongData")));
            net.controller().hold("main");
            net.controller().resume("main");
        }
        Set<Integer> named = new HashSet<>();
        for (NetworkEvent e : sink.events()) {
            if (e instanceof NodeNamedEvent n) {
                named.add(n.sourceId());
            } else if (!(e instanceof NetworkCommandEvent)) {
                assertThat(named).as("named before " + e).contains(e.sourceId());
            }
        }
        List<NetworkCommandEvent> commands = sink.events(NetworkCommandEvent.class);
        assertThat(commands).extracting(NetworkCommandEvent::command).contains(NetworkCommand.LOAD, NetworkCommand.CREATE,
                NetworkCommand.CONNECT, NetworkCommand.UNLOAD, NetworkCommand.DISCONNECT, NetworkCommand.DESTROY,
                NetworkCommand.HOLD, NetworkCommand.RESUME);
        assertThat(commands).filteredOn(c -> c.command() == NetworkCommand.UNLOAD)
                .singleElement().satisfies(c -> {
                    assertThat(c.paramsId()).isEqualTo("Extra");
                    assertThat(c.paramsType()).isEqualTo("module");
                    assertThat(c.sourceType()).isEqualTo("controller");
                });
        assertThat(commands).filteredOn(c -> c.command() == NetworkCommand.CONNECT)
                .allSatisfy(c -> assertThat(c.paramsId()).matches("\\d+>\\d+"));
        assertThat(sink.events(NodeNamedEvent.class)).extracting(NodeNamedEvent::kind).contains(NodeKind.DATA, NodeKind.RELATION);
    }
}
