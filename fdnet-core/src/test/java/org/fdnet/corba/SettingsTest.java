package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class SettingsTest {
    @Test
    void shouldBindToLoopbackUnlessToldOtherwise() {
        assertThat(OrbSettings.defaults().toOrbProperties().getProperty("OAIAddr")).isEqualTo("127.0.0.1");
        assertThat(OrbSettings.defaults().withBindAddress("10.0.0.5").toOrbProperties().getProperty("OAIAddr"))
                .isEqualTo("10.0.0.5");
    }

    @Test
    void shouldRefuseAWindowOfZeroWithTheValueInTheMessage() {
        assertThatThrownBy(() -> LinkSettings.defaults().withWindow(0))
                .isInstanceOf(IllegalArgumentException.class).hasMessage("window must be 1..64, was 0");
    }

    @Test
    void shouldRefuseACapacityThatIsNotAPowerOfTwo() {
        assertThatThrownBy(() -> new LinkSettings(4, 100, 1000, 100))
                .hasMessageContaining("power of two");
    }

    @Test
    void shouldRefuseANegativeSpinAndKeepTheSpinWhenTheWindowChanges() {
        assertThatThrownBy(() -> new LinkSettings(4, 100, 1024, 100, -1))
                .isInstanceOf(IllegalArgumentException.class).hasMessage("spinMicros must be 0..10000, was -1");
        assertThat(new LinkSettings(4, 100, 1024, 100, 0).withWindow(2).spinMicros()).isZero();
    }
}
