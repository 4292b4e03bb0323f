package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.fdnet.runtime.TestNetworks.*;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.HexFormat;
import java.util.List;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.event.NetworkEvent;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.loading.ClassLoadingPolicy;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** Simulated time: periods fire only when the driver advances the clock, on its thread, reproducibly. */
@Timeout(60)
class DrivenClockTest {
    private static final long ORIGIN = 1_700_000_000_000_000L;

    private static NetworkInfo sourceAndCopy() {
        NetworkInfo n = new NetworkInfo("driven");
        n.addNode("main", data("A", "DoubleData"));
        n.addNode("main", data("B", "DoubleData"));
        n.addNode("main", relation("Source", "PeriodicSource", "period=10", "frequency=1"));
        n.addNode("main", relation("Copy", "Expression", "expression=in0 * 2"));
        write(n, "main", "Source", "A");
        read(n, "main", "A", "Copy");
        write(n, "main", "Copy", "B");
        return n;
    }

    private static RuntimeNetwork startDriven(NetworkInfo n, DrivenClock clock, MemoryEventSink sink)
            throws RuntimeStartException {
        return RuntimeNetwork.start(n, options().drivenClock(clock).sink(sink));
    }

    @Test
    void shouldFirePeriodsOnlyWhenTheDriverAdvancesTheClock() throws Exception {
        MemoryEventSink sink = new MemoryEventSink();
        DrivenClock clock = new DrivenClock(ORIGIN);
        try (RuntimeNetwork net = startDriven(sourceAndCopy(), clock, sink)) {
            Thread.sleep(50); // wall time passes: nothing may fire; A holds only its initial value, stamped at start
            int initial = valuesOf(sink, net, "A").size();
            assertThat(valuesOf(sink, net, "A")).allMatch(e -> e.time() < ORIGIN + 1_000);

            net.advanceTo(95_000);

            List<DataValueEvent> a = valuesOf(sink, net, "A");
            assertThat(a.subList(initial, a.size())).extracting(DataValueEvent::time)
                    .containsExactly(ORIGIN + 10_000, ORIGIN + 20_000, ORIGIN + 30_000, ORIGIN + 40_000,
                            ORIGIN + 50_000, ORIGIN + 60_000, ORIGIN + 70_000, ORIGIN + 80_000, ORIGIN + 90_000);
            assertThat(clock.simMicros()).isEqualTo(95_000);
            assertThat(clock.micros()).isEqualTo(ORIGIN + 95_000);
        }
    }

    @Test
    void shouldRunTheNetworkToQuiescenceBeforeAdvanceToReturns() throws Exception {
        MemoryEventSink sink = new MemoryEventSink();
        DrivenClock clock = new DrivenClock(ORIGIN);
        try (RuntimeNetwork net = startDriven(sourceAndCopy(), clock, sink)) {
            net.advanceTo(250_000);
            // no waiting: the Relation downstream of the source ran on this thread before advanceTo returned
            Value a = net.controller().value(ref("A"));
            Value b = net.controller().value(ref("B"));
            assertThat(a.time()).isEqualTo(ORIGIN + 250_000);
            assertThat(b.asDouble()).isEqualTo(2 * a.asDouble());
            assertThat(b.time()).isGreaterThan(a.time());
            // the sine source read simulated seconds: sin(2π · 1 Hz · 0.25 s) = 1
            assertThat(a.asDouble()).isCloseTo(1.0, org.assertj.core.data.Offset.offset(1e-9));
        }
    }

    @Test
    void shouldRunWhatAnOutsideWriteMakesReadyBeforeTheWriteReturns() throws Exception {
        MemoryEventSink sink = new MemoryEventSink();
        DrivenClock clock = new DrivenClock(ORIGIN);
        try (RuntimeNetwork net = startDriven(sourceAndCopy(), clock, sink)) {
            net.advanceTo(5_000);
            net.controller().setValue(ref("A"), Value.of(21.0));
            assertThat(net.controller().value(ref("B")).asDouble()).isEqualTo(42.0);
            assertThat(net.controller().value(ref("A")).time()).isEqualTo(ORIGIN + 5_000);
        }
    }

    @Test
    void shouldGiveIdenticalEventLogsForTwoIdenticalSteppedRuns() throws Exception {
        Path file = Path.of("../networks/roq-motion.fdn");
        String first = steppedRunHash(file);
        String second = steppedRunHash(file);
        assertThat(second).isEqualTo(first);
    }

    private static String steppedRunHash(Path file) throws Exception {
        MemoryEventSink sink = new MemoryEventSink();
        RuntimeOptions o = RuntimeOptions.defaults().drivenClock(new DrivenClock(ORIGIN)).sink(sink)
                .classLoading(ClassLoadingPolicy.forNetworkFile(file, List.of()));
        try (RuntimeNetwork net = RuntimeNetwork.start(NetworkRepository.load(file), o)) {
            for (long t = 1_000; t <= 3_000_000; t += 1_000) {
                net.advanceTo(t);
                if (t == 1_000_000) {
                    net.controller().setValue(ref("Walk/I want to walk"), "0.5");
                }
                if (t == 2_000_000) {
                    assertThat(net.controller().unload("Walk").executed()).isTrue();
                }
            }
        }
        assertThat(sink.events(DataValueEvent.class).size()).as("values logged").isGreaterThan(1000);
        MessageDigest sha = MessageDigest.getInstance("SHA-256");
        for (NetworkEvent e : sink.events()) {
            sha.update(e.toString().getBytes(StandardCharsets.UTF_8));
        }
        return HexFormat.of().formatHex(sha.digest());
    }

    @Test
    void shouldRefuseToGoBackOrToBeDrivenOnTheWallClock() throws Exception {
        DrivenClock clock = new DrivenClock(ORIGIN);
        try (RuntimeNetwork net = startDriven(sourceAndCopy(), clock, new MemoryEventSink())) {
            net.advanceTo(20_000);
            assertThatThrownBy(() -> net.advanceTo(10_000)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("never goes back");
        }
        try (RuntimeNetwork wall = RuntimeNetwork.start(sourceAndCopy(), options())) {
            assertThatThrownBy(() -> wall.advanceTo(1_000)).isInstanceOf(IllegalStateException.class)
                    .hasMessageContaining("driven clock");
        }
        assertThatThrownBy(() -> options().drivenClock(clock).clock(new org.fdnet.event.EventClock()))
                .isInstanceOf(IllegalStateException.class);
    }

    private static List<DataValueEvent> valuesOf(MemoryEventSink sink, RuntimeNetwork net, String name) {
        int id = sink.events(org.fdnet.event.NodeNamedEvent.class).stream()
                .filter(e -> e.name().equals(ref(name))).mapToInt(NetworkEvent::sourceId).findFirst().orElseThrow();
        return sink.events(DataValueEvent.class).stream().filter(e -> e.sourceId() == id).toList();
    }
}
