package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The CPUs' wake-up latency request: held at 0 while open, the machine's own again once closed. */
class CpuLatencyHoldTest {
    @Test
    void shouldHoldTheWakeUpLatencyAtZeroUntilClosed() {
        long before = CpuLatencyHold.current();
        assertThat(before).as("nothing else holds the CPUs awake during this test").isGreaterThan(0);

        try (CpuLatencyHold held = CpuLatencyHold.hold()) {
            assertThat(CpuLatencyHold.current()).isZero();
        }

        assertThat(CpuLatencyHold.current()).isEqualTo(before);
    }
}
