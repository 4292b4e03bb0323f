package org.fdnet.testkit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.fdnet.runtime.Value;
import org.junit.jupiter.api.Test;

class TestNetworkTest {
    private static final Path LAB = Path.of("src/test/resources/networks/lab.fdn");

    @Test
    void shouldPropagateASetValueThroughItsRelationBeforeSetReturns() {
        try (TestNetwork net = TestNetwork.start(LAB)) {
            net.set("Lab/input", 0.25);

            net.assertValue("Lab/output").isCloseTo(0.5, 1e-12);
            assertThat(net.time()).isEqualTo(Duration.ZERO);
        }
    }

    @Test
    void shouldFirePeriodsOnlyAsSimulatedTimeAdvances() {
        try (TestNetwork net = TestNetwork.start(LAB)) {
            int before = net.history("Clock/tick").size();
            net.advance(Duration.ofMillis(100));

            List<Value> ticks = net.history("Clock/tick");
            assertThat(ticks.size() - before).isEqualTo(5);
            assertThat(ticks.get(ticks.size() - 1).time()).isEqualTo(100_000L);
            assertThat(net.time()).isEqualTo(Duration.ofMillis(100));
        }
    }

    @Test
    void shouldGiveTheSameValuesAndTimeStampsOnEveryRun() {
        assertThat(ticksOfARun()).isEqualTo(ticksOfARun());
    }

    private static List<String> ticksOfARun() {
        try (TestNetwork net = TestNetwork.start(LAB)) {
            net.advance(Duration.ofMillis(200));
            return net.history("Clock/tick").stream().map(v -> v.time() + ":" + v.text()).toList();
        }
    }

    @Test
    void shouldAwaitAValueInSimulatedTimeAndReturnIt() {
        try (TestNetwork net = TestNetwork.start(LAB)) {
            Value v = net.awaitValue("Clock/tick", x -> x.asDouble() > 0.9, Duration.ofSeconds(1));

            assertThat(v.asDouble()).isGreaterThan(0.9);
            assertThat(net.time()).as("sin(2π t) first exceeds 0.9 at the 20 ms period due at 0.18 s")
                    .isEqualTo(Duration.ofMillis(180));
        }
    }

    @Test
    void shouldFailAnAwaitWithTheNodeTheSimulatedTimeAndTheLastValue() {
        try (TestNetwork net = TestNetwork.start(LAB)) {
            assertThatThrownBy(() -> net.awaitValue("Lab/output", x -> x.asDouble() > 1, Duration.ofMillis(50)))
                    .isInstanceOf(AssertionError.class)
                    .hasMessageContaining("Lab/output never met the condition within 0.050 s")
                    .hasMessageContaining("now t = 0.050 s");
        }
    }

    @Test
    void shouldNameNodeTimeExpectationAndValueWhenAnAssertionFails() {
        try (TestNetwork net = TestNetwork.start(LAB)) {
            net.set("Lab/input", 1.0);
            net.advance(Duration.ofMillis(20));

            assertThatThrownBy(() -> net.assertValue("Lab/output").isCloseTo(3.0, 0.1))
                    .isInstanceOf(AssertionError.class)
                    .hasMessage("Lab/output at t = 0.020 s: expected 3.0 ± 0.1, was 2.0 (DOUBLE)");
        }
    }

    @Test
    void shouldRefuseANodeTheNetworkDoesNotDefine() {
        try (TestNetwork net = TestNetwork.start(LAB)) {
            assertThatThrownBy(() -> net.value("Lab/outptu"))
                    .isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("has no Data Lab/outptu");
        }
    }

    @Test
    void shouldStopAModuleItUnloads() {
        try (TestNetwork net = TestNetwork.start(LAB)) {
            net.advance(Duration.ofMillis(40));
            int before = net.history("Clock/tick").size();
            net.unload("Clock");
            net.advance(Duration.ofMillis(100));

            assertThat(net.history("Clock/tick")).hasSize(before);
            assertThat(net.relationFailures()).isEmpty();
        }
    }

    @Test
    void shouldNameTheFileAndTheProblemWhenTheNetworkDoesNotLoad() {
        assertThatThrownBy(() -> TestNetwork.start(Path.of("src/test/resources/networks/missing.fdn")))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("missing.fdn does not load");
    }
}
