package org.fdnet.roq.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.CourseLoader;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Pins what {@code bench roq --part push} measures (docs/roq-networks.md, "Disturbance"), one push on each side of
 * the measured limits, with margin: roq-reflex-bench on the flat course, noise seed 7, a 0.2 s push during the first
 * leg lift after 5.5 s, with the full network and with Balance and Reflex unloaded. The network helps against a
 * diagonal push mid-swing (45°, 0.2 s into the swing: largest survived 1025 N with it, 263 N without — a point off
 * the bench's default table) and hinders against a sideways one late in the swing (270°, 0.35 s: 478 N with it,
 * 1344 N without): the two findings, both pinned, so a change to Balance or the reflex that moves either shows.
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
    void shouldSurviveADiagonalPushMidSwingWithBalanceAndReflexThatTipsRoqOverWithoutThem() throws Exception {
        // 600 N: 0.59 × the 1025 N measured with the network, 2.3 × the 263 N without
        PushTrial.Outcome with = full.run(600, 45, 0.2);
        PushTrial.Outcome without = bare.run(600, 45, 0.2);
        assertThat(with.survived()).as("full network, 600 N at 45°: " + with).isTrue();
        assertThat(without.survived()).as("Balance and Reflex unloaded, 600 N at 45°: " + without).isFalse();
    }

    @Test
    void shouldSurviveASidewaysPushLateInTheSwingBetterWithoutBalanceAndReflexAsMeasured() throws Exception {
        // 850 N: 1.8 × the 478 N measured with the network, 0.63 × the 1344 N without
        PushTrial.Outcome with = full.run(850, 270, 0.35);
        PushTrial.Outcome without = bare.run(850, 270, 0.35);
        assertThat(with.survived()).as("full network, 850 N at 270°: " + with).isFalse();
        assertThat(without.survived()).as("Balance and Reflex unloaded, 850 N at 270°: " + without).isTrue();
    }
}
