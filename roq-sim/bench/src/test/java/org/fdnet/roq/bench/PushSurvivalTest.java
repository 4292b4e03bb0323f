package org.fdnet.roq.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.Push;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Pins what {@code bench roq --part push} measures (docs/roq-networks.md, "Disturbance"), one push between the
 * measured limits with and without the network, with margin on both sides: roq-reflex-bench on the flat course,
 * noise seed 7, a 0.2 s push during the first leg lift after 5.5 s, with the full network and with Balance and Reflex
 * unloaded. Three of the four points lie off the bench's table (22.5° steps, 0.2 s into the swing), which the reflex
 * was not chosen on; one pushes backwards, where session 5's network did no better than RoQ without it. Each push is
 * survived with the network and tips RoQ over without it, and is 2.5–4 × the largest push RoQ survives without them
 * (and under a third of the network's): a change to Balance or the reflex that loses the 1.5× gain there shows here. Sideways (60–120° off the crawl's line) no point is pinned: above ~500 N RoQ is thrown across the floor and
 * which forces it survives is too irregular for one push to stand for a limit (docs/roq-networks.md).
 */
class PushSurvivalTest {
    private static final Path NETWORK = Path.of("..", "..", "networks", "roq-reflex-bench.fdn");
    private static PushTrial full;
    private static PushTrial bare;

    @BeforeAll
    static void setUp() throws Exception {
        NetworkInfo network = NetworkRepository.load(NETWORK);
        full = new PushTrial(network, CourseLoader.resolve("flat"), 7);
        bare = new PushTrial(network, CourseLoader.resolve("flat"), 7, PushSurvivalBench.UNLOADED);
    }

    @Test
    void shouldSurviveAForwardPushAtLiftOffThatTipsRoqOverWithoutBalanceAndReflex() throws Exception {
        // on the table: 0°, 0 s; 450 N is 0.29 × the 1550 N below which every push is survived with the network (session
        // 8's 14 cm crouch) and 3 × the 150 N without it, where every push from 200 N to 800 N tips RoQ over
        assertSurvivedOnlyWithTheNetwork(450, 0, 0);
    }

    @Test
    void shouldSurviveAForwardLeftPushMidSwingThatTipsRoqOverWithoutThem() throws Exception {
        // off the table: 22.5°, 0.2 s; 600 N is 0.3 × the network's 2000 N (the bench's largest push), 4 × the 150 N
        // without (every push from 200 N to 800 N tips it over)
        assertSurvivedOnlyWithTheNetwork(600, 22.5, 0.2);
    }

    @Test
    void shouldSurviveAForwardRightPushMidSwingThatTipsRoqOverWithoutThem() throws Exception {
        // off the table: 337.5°, 0.2 s; 600 N is 0.34 × the network's 1750 N, 4 × the 150 N without (every push from
        // 200 N to 800 N tips it over)
        assertSurvivedOnlyWithTheNetwork(600, 337.5, 0.2);
    }

    @Test
    void shouldSurviveABackwardPushMidSwingThatTipsRoqOverWithoutThem() throws Exception {
        // off the table: 202.5°, 0.2 s; 500 N is 0.26 × the network's 1900 N, 2.5 × the 200 N without (every push from
        // 250 N to 800 N tips it over; session 6's network survived 300 N)
        assertSurvivedOnlyWithTheNetwork(500, 202.5, 0.2);
    }

    @Test
    void shouldCountEveryPushOfAWholeScanButStopAtTheFirstFailureOtherwise() throws Exception {
        // survived below 300 N, not at 300, again from 350 to 600 N, not from 650 N on
        PushTrial.Pushing pattern = force -> new PushTrial.Outcome(force < 300 || force > 320 && force < 620, 0, 0, 1);
        PushTrial.Scan whole = PushTrial.scan(pattern, 50, true);
        PushTrial.Scan first = PushTrial.scan(pattern, 50, false);
        assertThat(whole.throughout()).isEqualTo(250);
        assertThat(whole.survived()).isEqualTo(5 + 6);
        assertThat(whole.tried()).isEqualTo((int) (Push.MAX_FORCE / 50));
        assertThat(first.throughout()).isEqualTo(250);
        assertThat(first.tried()).isEqualTo(6);
        assertThat(first.survived()).isEqualTo(5);
    }

    private static void assertSurvivedOnlyWithTheNetwork(double force, double direction, double offset)
            throws Exception {
        PushTrial.Outcome with = full.run(force, direction, offset);
        PushTrial.Outcome without = bare.run(force, direction, offset);
        String push = force + " N at " + direction + "°, " + offset + " s into the swing: ";
        assertThat(with.survived()).as("full network, " + push + with).isTrue();
        assertThat(without.survived()).as("Balance and Reflex unloaded, " + push + without).isFalse();
    }
}
