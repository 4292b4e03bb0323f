package org.fdnet.roq.testkit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.junit.jupiter.api.Test;

class SimulatedRoqTest {
    static final Path RUBBLE_NETWORK = Path.of("../../networks/roq-rubble.fdn");

    @Test
    void shouldGiveTheSameStateHashWhenTheSameRunIsRepeated() {
        String first = hashAfter(5, 3);
        String second = hashAfter(5, 3);
        String otherNoise = hashAfter(5, 4);

        assertThat(second).isEqualTo(first);
        assertThat(otherNoise).as("another noise seed gives another robot").isNotEqualTo(first);
    }

    @Test
    void shouldGiveTheSameRobotWhenRunsShareTheProcessInParallel() throws Exception {
        String alone = hashAfter(6, 2);
        ExecutorService pool = Executors.newFixedThreadPool(2);
        try {
            Future<String> first = pool.submit(() -> hashAfter(6, 2));
            Future<String> second = pool.submit(() -> hashAfter(6, 2));

            assertThat(first.get()).isEqualTo(alone);
            assertThat(second.get()).isEqualTo(alone);
        } finally {
            pool.shutdownNow();
        }
    }

    private static String hashAfter(long noise, int seconds) {
        try (SimulatedRoq roq = SimulatedRoq.builder().network(RUBBLE_NETWORK).course("rubble:12").noise(noise).start()) {
            roq.advance(Duration.ofSeconds(seconds));
            assertThat(roq.time()).isEqualTo(Duration.ofSeconds(seconds));
            return roq.stateHash();
        }
    }

    @Test
    void shouldGiveTheSameEventLogHashWhenTheSameRunIsRepeatedAtAnotherWallClockTime() throws Exception {
        String first = eventLogHashAfter(SimulatedRoq.builder().noise(5));
        Thread.sleep(5); // the next run's driven clock starts at another wall-clock microsecond
        String second = eventLogHashAfter(SimulatedRoq.builder().noise(5));
        String otherNoise = eventLogHashAfter(SimulatedRoq.builder().noise(6));

        assertThat(second).isEqualTo(first);
        assertThat(otherNoise).as("other sensor readings give other values").isNotEqualTo(first);
    }

    private static String eventLogHashAfter(SimulatedRoq.Builder builder) {
        try (SimulatedRoq roq = builder.network(RUBBLE_NETWORK).course("flat").start()) {
            roq.advance(Duration.ofSeconds(1));
            assertThat(roq.network().events()).hasSizeGreaterThan(100);
            return roq.eventLogHash();
        }
    }

    @Test
    void shouldRunWithoutSensorNoiseWhenAskedAndSayItInItsName() {
        String noisy;
        try (SimulatedRoq roq = SimulatedRoq.builder().network(RUBBLE_NETWORK).course("flat").noise(5).start()) {
            roq.advance(Duration.ofSeconds(1));
            noisy = roq.eventLogHash();
        }
        String[] exact = new String[2];
        for (int i = 0; i < 2; i++) {
            try (SimulatedRoq roq = SimulatedRoq.builder().network(RUBBLE_NETWORK).course("flat").noise(5 + i)
                    .withoutNoise().start()) {
                roq.advance(Duration.ofSeconds(1));
                exact[i] = roq.eventLogHash();
                assertThat(roq.name()).isEqualTo("roq-rubble.fdn on flat, noise off");
            }
        }

        assertThat(exact[1]).as("without noise the seed changes nothing").isEqualTo(exact[0]);
        assertThat(exact[0]).as("without noise the network reads other values").isNotEqualTo(noisy);
    }

    @Test
    void shouldMeasureAWalkAndRunHooksEveryStep() {
        try (SimulatedRoq roq = SimulatedRoq.builder().network(RUBBLE_NETWORK).course("flat").noise(2).start()) {
            int[] steps = new int[2];
            roq.beforeEachStep(r -> steps[0]++);
            roq.afterEachStep(r -> steps[1]++);

            roq.runUntil("0.15 m walked", r -> r.measures().distance() > 0.15, Duration.ofSeconds(20));

            assertThat(roq.measures().distance()).isGreaterThan(0.15);
            assertThat(steps[0]).isEqualTo(steps[1]).isEqualTo((int) (roq.time().toMillis() / 10));
            roq.assertThat().noFall().trackErrorAtMost(0.3).tiltAtMost(0.5).noLoadedFootBreakthrough();
        }
    }

    @Test
    void shouldNameTheSimulatedTimeAndTheFigureWhenAnAssertionFails() {
        try (SimulatedRoq roq = SimulatedRoq.builder().network(RUBBLE_NETWORK).course("flat").noise(2).start()) {
            roq.advance(Duration.ofMillis(500));

            assertThatThrownBy(() -> roq.assertThat().walkedAtLeast(2.0))
                    .isInstanceOf(AssertionError.class)
                    .hasMessageStartingWith("roq-rubble.fdn on flat, noise 2 at t = 0.50 s: walked ")
                    .hasMessageContaining("expected at least 2.000 m");
            assertThatThrownBy(() -> roq.runUntil("a 3 m walk", r -> r.measures().distance() > 3, Duration.ofMillis(200)))
                    .hasMessageContaining("a 3 m walk did not happen within 0.20 s of simulated time");
            assertThat(roq.time()).isEqualTo(Duration.ofMillis(700));
        }
    }

    @Test
    void shouldRefuseAModuleTheNetworkDoesNotHave() {
        assertThatThrownBy(() -> SimulatedRoq.builder().network(RUBBLE_NETWORK).unload("NoSuchModule").start())
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("NoSuchModule");
    }

    @Test
    void shouldNameWhatIsWrongWithACourseSpec() {
        assertThatThrownBy(() -> CourseSpec.parse("rubble:twelve"))
                .hasMessageContaining("course 'rubble:twelve': after 'rubble:' comes a seed");
        assertThatThrownBy(() -> CourseSpec.parse("moon"))
                .hasMessageContaining("course 'moon'");
        assertThat(CourseSpec.parse("slope:-15").name()).isEqualTo("slope-15");
    }
}
