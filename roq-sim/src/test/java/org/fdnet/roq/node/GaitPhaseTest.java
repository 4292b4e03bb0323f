package org.fdnet.roq.node;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.fdnet.runtime.Value;
import org.junit.jupiter.api.Test;

class GaitPhaseTest {
    @Test
    void theFiveNumbersRoundTrip() {
        GaitPhase p = new GaitPhase(2, false, 7, 3, 0.25);
        assertThat(GaitPhase.of(p.value())).isEqualTo(p);
        assertThat(p.proving()).isTrue();
        assertThat(p.upLeg()).isEqualTo(2);
    }

    @Test
    void theOlderCrawlsShorterPhaseReadsWithNoLegBeingUnloaded() {
        GaitPhase p = GaitPhase.of(Value.ofDoubles(1, 1, 0));
        assertThat(p).isEqualTo(new GaitPhase(1, true, 0, -1, 0));
        assertThat(GaitPhase.of(Value.ofDoubles(0, 0))).isEqualTo(new GaitPhase(0, false, 0, -1, 0));
    }

    @Test
    void aMissingShortOrOutOfRangeValueReadsAsStanding() {
        assertThat(GaitPhase.of(null)).isEqualTo(GaitPhase.STANDING);
        assertThat(GaitPhase.of(Value.ofDoubles(1))).isEqualTo(GaitPhase.STANDING);
        assertThat(GaitPhase.of(Value.ofDoubles(4, 0, 0))).isEqualTo(GaitPhase.STANDING);
        assertThat(GaitPhase.of(Value.ofDoubles(1, 0, 0, 2, 1.5))).isEqualTo(GaitPhase.STANDING);
        assertThat(GaitPhase.STANDING.upLeg()).isEqualTo(-1);
    }

    @Test
    void aBadPhaseIsRefusedNamingTheField() {
        assertThatThrownBy(() -> new GaitPhase(0, false, 0, 5, 0)).hasMessageContaining("unloading leg");
        assertThatThrownBy(() -> new GaitPhase(0, false, 0, -1, 2)).hasMessageContaining("unloaded share");
    }
}
