package org.fdnet.roq.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.testkit.RoqMeasures;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * {@code bench roq --part breakthroughs} on the {@code crossing} course, two noise seeds, 40 s: the sums it prints
 * are those of the runs, and probing is what keeps the crusts from breaking under loaded feet — without module
 * Probing every crust stepped on breaks under load (measured: these two runs 0 against 12, 7 crusts found by the
 * probes; 128 against 34 over 24 seeds of 100 s).
 */
@Timeout(300)
class BreakthroughSweepTest {
    private static final Path NETWORK = Path.of("..", "..", "networks", "roq-rubble.fdn");

    @Test
    void shouldCountFewerLoadedFootBreakthroughsWithProbingThanWithout() throws Exception {
        BreakthroughSweep sweep = new BreakthroughSweep(NetworkRepository.load(NETWORK), CourseLoader.resolve("crossing"),
                new long[] {30, 31}, 40);
        BreakthroughSweep.Sum probed = sweep.run();
        assertThat(probed.runs()).isEqualTo(2);
        assertThat(probed.fallen()).as("runs fallen").isZero();
        assertThat(probed.leastWalked()).as("least walked, m").isGreaterThan(1.0);
        assertThat(probed.probeBroken()).as("crusts the probes found").isPositive();
        BreakthroughSweep.Sum unprobed = sweep.baseline();
        assertThat(unprobed.probeBroken()).as("without Probing no probe breaks a crust").isZero();
        assertThat(probed.loaded()).as("loaded-foot breakthroughs with Probing, against %d without", unprobed.loaded())
                .isLessThan(unprobed.loaded());
        // unprobed, crusts break under the feet that stand on them; each break is told at most once
        assertThat(unprobed.standing()).as("without Probing, breaks under a standing foot").isPositive();
        assertThat(unprobed.swinging() + unprobed.standing()).isLessThanOrEqualTo(unprobed.loaded());
        assertThat(probed.swinging() + probed.standing()).isLessThanOrEqualTo(probed.loaded());
    }

    /** Two runs of 10 s are 2,000 steps of 10 ms; 500 of them with a joint at its torque limit are a quarter. */
    @Test
    void shouldSumTheStepsWithAJointAtItsTorqueLimitAndSayWhatPartOfTheTimeTheyAre() {
        RoqMeasures m = new RoqMeasures(10, 0.4, 0.01, 0.01, 0.05, false, 1, 0, 0, 0, 0, Double.NaN);
        BreakthroughSweep.Sum sum = BreakthroughSweep.Sum.of(List.of(new MeasuredWalk("a", m, 3, 200),
                new MeasuredWalk("b", m, 4, 300)), 10);
        assertThat(sum.strained()).isEqualTo(500);
        assertThat(sum.slack()).isEqualTo(7);
        assertThat(sum.line("sum")).contains("a joint at its torque limit 25 % of the time");
    }

    @Test
    void shouldReadNoiseSeedsAsARangeOrAListAndRefuseAnythingElse() {
        assertThat(NoiseSeeds.parse("3-6")).containsExactly(3, 4, 5, 6);
        assertThat(NoiseSeeds.parse("7, 11,2004")).containsExactly(7, 11, 2004);
        assertThat(NoiseSeeds.parse("6-3")).isEmpty();
        assertThat(NoiseSeeds.parse("1-5000")).isEmpty();
        assertThat(NoiseSeeds.parse("a,b")).isEmpty();
        assertThat(NoiseSeeds.parse("")).isEmpty();
        assertThat(NoiseSeeds.parse("99999999999999999999")).isEmpty();
    }
}
