package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.fdnet.runtime.TestNetworks.*;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.HexFormat;
import java.util.List;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.event.NetworkEvent;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.runtime.engine.DrivenClock;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class DrivenClockTest {
    private static final long START = 1_700_000_000_000_000L;

    /** Two periodic sources (10 ms and 25 ms) feeding a chain and a join: periods coincide every 50 ms. */
    private static NetworkInfo network() {
        NetworkInfo n = new NetworkInfo("stepped");
        n.addNode("main", data("Saw", "DoubleData"));
        n.addNode("main", data("Slow", "DoubleData"));
        n.addNode("main", data("Sum", "DoubleData"));
        n.addNode("main", data("Avg", "DoubleData"));
        n.addNode("main", relation("Clock", "PeriodicSource", "period=10", "waveform=sawtooth", "amplitude=0.5",
                "offset=0.5"));
        n.addNode("main", relation("Wave", "PeriodicSource", "period=25"));
        n.addNode("main", relation("Add", "Expression", "expression=in0 + in1"));
        n.addNode("main", relation("Smooth", "MovingAverage", "window=4"));
        write(n, "main", "Clock", "Saw");
        write(n, "main", "Wave", "Slow");
        read(n, "main", "Saw", "Add");
        read(n, "main", "Slow", "Add");
        write(n, "main", "Add", "Sum");
        read(n, "main", "Sum", "Smooth");
        write(n, "main", "Smooth", "Avg");
        return n;
    }

    private static RuntimeOptions stepped(DrivenClock clock, MemoryEventSink sink) {
        return options().drivenClock(clock).sink(sink);
    }

    private static String steppedRunHash() throws Exception {
        MemoryEventSink sink = new MemoryEventSink();
        try (RuntimeNetwork net = RuntimeNetwork.start(network(), stepped(new DrivenClock(START), sink))) {
            for (int ms = 1; ms <= 2000; ms++) {
                net.advanceTo(START + ms * 1000L);
            }
            net.controller().unload("main");
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw new AssertionError(e);
        }
        MessageDigest sha = MessageDigest.getInstance("SHA-256");
        List<NetworkEvent> events = sink.events();
        assertThat(events.size()).isGreaterThan(500);
        for (NetworkEvent e : events) {
            sha.update(e.toString().getBytes(StandardCharsets.UTF_8));
        }
        return HexFormat.of().formatHex(sha.digest());
    }

    @Test
    void shouldGiveTheSameEventLogEventByEventForTwoIdenticalSteppedRuns() throws Exception {
        assertThat(steppedRunHash()).isEqualTo(steppedRunHash());
    }

    @Test
    void shouldFirePeriodsOnlyWhenTheDriverAdvancesAndReadSecondsFromTheDrivenClock() throws Exception {
        MemoryEventSink sink = new MemoryEventSink();
        try (RuntimeNetwork net = RuntimeNetwork.start(network(), stepped(new DrivenClock(START), sink))) {
            assertThat(net.workerThreads()).isZero();
            long atStart = net.firings();
            Thread.sleep(50);
            assertThat(net.firings()).as("nothing fires while the driver stands still").isEqualTo(atStart);
            net.advanceTo(START + 250_000);
            // sawtooth 0.5 + 0.5 * (2 frac(t) - 1) = frac(t): t read from the driven clock, 0.25 s
            assertThat(net.controller().value(ref("Saw")).asDouble()).isCloseTo(0.25, org.assertj.core.data.Offset.offset(1e-9));
            List<DataValueEvent> saws = sink.events(DataValueEvent.class).stream()
                    .filter(e -> e.value().text().startsWith("0.25")).toList();
            assertThat(saws).isNotEmpty();
            assertThat(saws.get(0).time()).as("stamped at simulated time").isBetween(START + 250_000, START + 250_100);
            long clockFirings = 25;
            long waveFirings = 10;
            assertThat(net.firings() - atStart).as("every period up to 250 ms, and what they caused, ran before advanceTo returned")
                    .isGreaterThanOrEqualTo(clockFirings + waveFirings);
            assertThat(net.timeMicros()).isEqualTo(START + 250_000);
        }
    }

    @Test
    void shouldRunEveryFiringOnTheDriversThread() throws Exception {
        MemoryEventSink sink = new MemoryEventSink();
        NetworkInfo n = network();
        try (RuntimeNetwork net = RuntimeNetwork.start(n, stepped(new DrivenClock(START), sink))) {
            net.advanceTo(START + 100_000);
            assertThat(Thread.getAllStackTraces().keySet().stream().map(Thread::getName)
                    .filter(name -> name.startsWith("fdnet-period") || name.startsWith("fdnet-worker")))
                    .as("a driven network has no timer or worker threads").isEmpty();
        }
    }

    @Test
    void shouldRefuseToGoBackOrToBeDrivenOnTheWallClock() throws Exception {
        try (RuntimeNetwork net = RuntimeNetwork.start(network(), stepped(new DrivenClock(START), new MemoryEventSink()))) {
            net.advanceTo(START + 10_000);
            assertThatThrownBy(() -> net.advanceTo(START)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("lies before");
        }
        try (RuntimeNetwork net = RuntimeNetwork.start(network(), options())) {
            assertThatThrownBy(() -> net.advanceTo(START)).isInstanceOf(IllegalStateException.class)
                    .hasMessageContaining("drivenClock");
        }
    }
}
