package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Set;
import java.util.UUID;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.ValueType;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;

/** A host's trace buffer: bounded, never waits, drops and counts, leaves stand-ins out. */
class HostTraceTest {
    private static final NodeRef LEVEL = new NodeRef("main", "Level");
    private static final NodeRef SHADOW = new NodeRef("main", "Shadow");

    @Test
    void shouldKeepAtMostItsCapacityAndCountWhatItDropped() {
        HostTrace trace = new HostTrace(UUID.randomUUID(), 3, Set.of()::contains);
        trace.accept(new NodeNamedEvent(1, 10, NodeKind.DATA, LEVEL));
        for (int i = 1; i <= 9; i++) {
            trace.accept(new DataValueEvent(1, 10 + i, ValueType.DOUBLE, Double.toString(i)));
        }

        HostTrace.Batch first = trace.take(100);
        assertThat(first.lines()).extracting(HostTrace.Line::text)
                .containsExactly("named    #1 Data main/Level", "value    main/Level = 1.0", "value    main/Level = 2.0");
        assertThat(first.lines()).extracting(HostTrace.Line::timeMicros).containsExactly(10L, 11L, 12L);
        assertThat(first.dropped()).isEqualTo(7);

        HostTrace.Batch second = trace.take(100);
        assertThat(second.lines()).isEmpty();
        assertThat(second.dropped()).isZero();
    }

    @Test
    void shouldNameANodeEvenWhenItsNamingWasDropped() {
        HostTrace trace = new HostTrace(UUID.randomUUID(), 1, Set.of()::contains);
        trace.accept(new DataValueEvent(2, 1, ValueType.DOUBLE, "0.5"));
        trace.accept(new NodeNamedEvent(2, 2, NodeKind.DATA, LEVEL)); // dropped: the buffer is full
        trace.take(10);
        trace.accept(new DataValueEvent(2, 3, ValueType.DOUBLE, "0.75"));

        assertThat(trace.take(10).lines()).extracting(HostTrace.Line::text)
                .containsExactly("value    main/Level = 0.75");
    }

    @Test
    void shouldLeaveOutTheEventsOfStandIns() {
        HostTrace trace = new HostTrace(UUID.randomUUID(), 100, Set.of(SHADOW)::contains);
        trace.accept(new NodeNamedEvent(1, 1, NodeKind.DATA, LEVEL));
        trace.accept(new NodeNamedEvent(2, 2, NodeKind.DATA, SHADOW));
        trace.accept(new DataValueEvent(2, 3, ValueType.DOUBLE, "9.0"));
        trace.accept(new DataValueEvent(1, 4, ValueType.DOUBLE, "1.0"));

        assertThat(trace.take(10).lines()).extracting(HostTrace.Line::text)
                .containsExactly("named    #1 Data main/Level", "value    main/Level = 1.0");
    }

    @Test
    void shouldCutAVeryLongValueSoABatchStaysSmall() {
        HostTrace trace = new HostTrace(UUID.randomUUID(), 10, Set.of()::contains);
        trace.accept(new DataValueEvent(1, 1, ValueType.STRING, "x".repeat(100_000)));

        String line = trace.take(10).lines().get(0).text();
        assertThat(line).hasSize(HostTrace.MAX_LINE_CHARS).endsWith("...");
    }
}
