package org.fdnet.corba.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

/** bench corba's sustained stream counts what arrives, not the last number it saw. */
class ArrivalCountTest {
    private static final long WINDOW = 10_000;

    @Test
    void shouldCountArrivalsSoALostValueIsMissingEvenWhenALaterOneArrives() {
        ArrivalCount count = new ArrivalCount(WINDOW);
        count.start(0);
        count.arrived(0, 1);
        count.arrived(1, 2);
        count.arrived(3, 3); // 2 was lost: the last number + 1 would claim 4 arrived

        assertThat(count.received()).isEqualTo(3);
        assertThat(count.unexpected()).isEqualTo(1);
    }

    @Test
    void shouldCountRepeatsAndOutOfOrderArrivalsAsUnexpected() {
        ArrivalCount count = new ArrivalCount(WINDOW);
        count.start(0);
        count.arrived(0, 1);
        count.arrived(0, 2);
        count.arrived(2, 3);
        count.arrived(1, 4);

        assertThat(count.received()).isEqualTo(4);
        assertThat(count.unexpected()).isEqualTo(3);
    }

    @Test
    void shouldShowAStallAsAnEmptyWindow() {
        ArrivalCount count = new ArrivalCount(WINDOW);
        count.start(1_000);
        count.arrived(0, 1_000 + 5);
        count.arrived(1, 1_000 + WINDOW - 1);
        count.arrived(2, 1_000 + WINDOW + 1);
        count.arrived(3, 1_000 + 3 * WINDOW + 7);

        assertThat(count.perWindow()).containsExactly(2, 1, 0, 1);
        assertThat(count.seconds()).isEqualTo((3 * WINDOW + 7) / 1e9);
    }

    @Test
    void shouldRejectAWindowThatIsNotPositive() {
        assertThatThrownBy(() -> new ArrivalCount(0)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("window must be positive");
    }
}
