package org.fdnet.testkit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.platform.engine.discovery.DiscoverySelectors.selectClass;
import static org.junit.platform.testkit.engine.EventConditions.event;
import static org.junit.platform.testkit.engine.EventConditions.finishedWithFailure;
import static org.junit.platform.testkit.engine.EventConditions.test;
import static org.junit.platform.testkit.engine.TestExecutionResultConditions.message;

import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.platform.testkit.engine.EngineTestKit;

class FdnetExtensionTest {
    /** Run by EngineTestKit below, not by Surefire (the nested class is not static-discoverable as a Test). */
    @FdnetTest
    static class UsesTheKit {
        static TestNetwork last;

        @Test
        void passes(@NetworkFile("src/test/resources/networks/lab.fdn") TestNetwork net) {
            last = net;
            net.set("Lab/input", 2.0);
            net.assertValue("Lab/output").isCloseTo(4.0, 1e-12);
        }

        @Test
        void fails(@NetworkFile("src/test/resources/networks/lab.fdn") TestNetwork net) {
            net.advance(Duration.ofMillis(40));
            net.assertValue("Lab/output").isGreaterThan(1);
        }

        @Test
        void namesAMissingFile(@NetworkFile("src/test/resources/networks/none.fdn") TestNetwork net) {
            net.advance(Duration.ofMillis(1));
        }
    }

    @Test
    void shouldStartEachNetworkForItsTestAndReportFailuresWithTheSimulatedTime() {
        var results = EngineTestKit.engine("junit-jupiter").selectors(selectClass(UsesTheKit.class)).execute()
                .testEvents();

        results.assertStatistics(s -> s.started(3).succeeded(1).failed(2));
        results.assertThatEvents()
                .haveExactly(1, event(test("fails"), finishedWithFailure(
                        message("Lab/output at t = 0.040 s: expected more than 1.0, was 0.0 (DOUBLE)"))))
                .haveExactly(1, event(test("namesAMissingFile"), finishedWithFailure(
                        message(m -> m.contains("none.fdn does not load")))));
    }

    @Test
    void shouldCloseTheNetworkAfterTheTest() {
        EngineTestKit.engine("junit-jupiter").selectors(selectClass(UsesTheKit.class)).execute();

        assertThat(UsesTheKit.last).isNotNull();
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> UsesTheKit.last.advance(Duration.ofMillis(1)))
                .hasMessageContaining("closed");
    }
}
