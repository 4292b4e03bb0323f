package org.fdnet.logger.soak;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;

class FaultPlanTest {
    @Test
    void shouldPlanEveryNetworkKindOnceInAnApartMinute() {
        FaultPlan plan = FaultPlan.apart(Duration.ofSeconds(60), FaultPlan.APART_ORDER);
        assertThat(plan.faults()).extracting(FaultPlan.Planned::kind).containsExactly(FaultKind.HOST_PARTITION,
                FaultKind.LOGGER_PARTITION, FaultKind.NAMING_PARTITION, FaultKind.THROTTLE, FaultKind.LOSS);
        for (FaultPlan.Planned f : plan.faults()) {
            assertThat(f.atMillis() + f.lengthMillis()).as(f.toString()).isLessThanOrEqualTo(60_000);
        }
    }

    @Test
    void shouldHoldEveryKindAndTheLongPartitionsInHalfAnHour() {
        List<FaultPlan.Planned> faults = FaultPlan.apart(Duration.ofMinutes(30), FaultPlan.APART_ORDER).faults();
        assertThat(faults).extracting(FaultPlan.Planned::kind).contains(FaultKind.values());
        assertThat(faults).filteredOn(f -> f.kind() == FaultKind.HOST_PARTITION).extracting(FaultPlan.Planned::lengthMillis)
                .contains(5_000L, 30_000L, 120_000L);
        assertThat(faults).filteredOn(f -> f.kind() == FaultKind.LOSS).extracting(FaultPlan.Planned::lengthMillis)
                .contains(60_000L);
        for (int i = 1; i < faults.size(); i++) {
            FaultPlan.Planned before = faults.get(i - 1);
            assertThat(faults.get(i).atMillis()).as("faults one after the other: " + before + " then " + faults.get(i))
                    .isGreaterThanOrEqualTo(before.atMillis() + before.lengthMillis());
        }
        FaultPlan.Planned last = faults.get(faults.size() - 1);
        assertThat(last.atMillis() + last.lengthMillis()).isLessThanOrEqualTo(Duration.ofMinutes(30).toMillis());
    }

    @Test
    void shouldRefuseAnUnknownCycleNamingTheKnownOnes() {
        assertThatThrownBy(() -> FaultPlan.apart(Duration.ofSeconds(60), List.of("partition45")))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("--cycles: no cycle 'partition45'; known: network, plain, partition30, loss, partition120");
    }

    @Test
    void shouldRefuseARunShorterThanItsFirstCycle() {
        assertThatThrownBy(() -> FaultPlan.apart(Duration.ofSeconds(120), List.of("partition120")))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("--for must be at least 180s to fit the partition120 cycle with time to heal, was 120s");
    }
}
