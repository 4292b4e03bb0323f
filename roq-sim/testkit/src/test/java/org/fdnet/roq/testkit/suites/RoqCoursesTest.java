package org.fdnet.roq.testkit.suites;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.assertj.core.api.SoftAssertions;
import org.fdnet.roq.testkit.RoqAssertions;
import org.fdnet.roq.testkit.RoqMeasures;
import org.fdnet.roq.testkit.SimulatedRoq;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * roq-rubble.fdn (and roq-walk.fdn on level ground) on every built-in course and on courses it was not tuned on — five
 * rubble seeds with blocks up to 6 cm, 15° up and down — with seeded sensor noise as in the demo. Every run must keep
 * RoQ up, break at most the stated number of cells under a loaded foot (up to 2 a run on {@code fragile} and
 * {@code crossing}, see below), stay near its course line and heading (averaged over a crawl cycle), tilt no more than the
 * ground asks, and walk at least a distance set 20 % or more below the median measured over these runs
 * (docs/explanation/roq-control.md lists the measured figures; every row was also run on eight noise seeds and every bound held
 * except the two comparisons, which therefore run on several noise seeds: Posture on 18° down, Course as a mean over
 * eight). The runs are independent simulated robots, two at a time.
 */
@Timeout(900)
class RoqCoursesTest {
    private static final Logger LOG = LoggerFactory.getLogger(RoqCoursesTest.class);
    private static final Path RUBBLE = Path.of("../../networks/roq-rubble.fdn");
    private static final Path WALK = Path.of("../../networks/roq-walk.fdn");
    /** Simulated seconds per run. */
    private static final int SECONDS = 40;
    /** Rubble seeds besides the built-in course's 2004 (21: a block there can stall the crawl and turn it). */
    private static final long[] SEEDS = {11, 12, 13, 21};

    /** Simulated seconds of the heading runs: about 3 m of rubble (5 s of them standing while the gyro settles). */
    private static final int HEADING_SECONDS = 70;
    /**
     * Noise seeds of the heading runs. One run tells little: over 3 m the drift without Course ranged 0.18–0.91 m
     * over eight seeds, so the comparison is of means.
     */
    private static final long[] HEADING_NOISE = {5, 105, 205, 305, 405, 505, 605, 705};
    private static final String HELD = "roq-rubble rubble 12, 70 s, noise ";
    private static final String UNHELD = "roq-rubble rubble 12, 70 s, module Course unloaded, noise ";
    private static final String DOWN = "roq-rubble slope 15 down";
    /** Noise seeds of the descents with and without Posture. */
    private static final long[] STEEP_NOISE = {40, 140};
    private static final String STEEP = "roq-rubble slope 18 down, noise ";
    private static final String STEEP_UNLEVELLED = "roq-rubble slope 18 down, module Posture unloaded, noise ";

    /**
     * Off the course line, averaged over a cycle, m: protects the heading and track hold. Measured at most 0.21 (rubble
     * seed 14) over these runs; the bound is 1.65× that, above the scatter between noise seeds.
     */
    private static final double MAX_TRACK = 0.35;
    /** Off the heading, averaged over a cycle, rad: measured at most 0.27 (fragile); the bound 1.65× that, as above. */
    private static final double MAX_HEADING = 0.45;
    /**
     * Largest roll or pitch on level ground and rubble, rad: protects Balance and Posture against rocking the body.
     * Measured at most 0.06 level and 0.24 on rubble; the bound leaves rubble's worst 0.16 rad of room and stays
     * below FallDetector's 0.6.
     */
    private static final double LEVEL_TILT = 0.4;
    /** Largest roll or pitch beyond the slope, rad: Posture levels the body; measured at most 0.05 beyond 15°, 3× that. */
    private static final double SLOPE_TILT = 0.15;

    /** What a finished run measured, and the kit's assertions on it. */
    private record Walk(RoqMeasures measures, RoqAssertions then) {
    }

    private static final Map<String, Future<Walk>> RUNS = new LinkedHashMap<>();
    private static ExecutorService pool;

    @BeforeAll
    static void startRuns() {
        pool = Executors.newFixedThreadPool(2);
        start("roq-walk flat", WALK, "flat", 1);
        start("roq-rubble flat", RUBBLE, "flat", 2);
        start("roq-rubble slope (built-in, 10 up)", RUBBLE, "slope", 3);
        start("roq-rubble slope 15 up", RUBBLE, "slope:15", 4);
        start(DOWN, RUBBLE, "slope:-15", 40);
        for (long noise : STEEP_NOISE) {
            start(STEEP + noise, RUBBLE, "slope:-18", SECONDS, noise);
            start(STEEP_UNLEVELLED + noise, RUBBLE, "slope:-18", SECONDS, noise, "Posture");
        }
        start("roq-rubble rubble 2004", RUBBLE, "rubble", 5);
        for (long seed : SEEDS) {
            start("roq-rubble rubble " + seed, RUBBLE, "rubble:" + seed, 5 + seed);
        }
        start("roq-rubble fragile", RUBBLE, "fragile", 30);
        start("roq-rubble crossing", RUBBLE, "crossing", 31);
        for (long noise : HEADING_NOISE) {
            start(HELD + noise, RUBBLE, "rubble:12", HEADING_SECONDS, noise);
            start(UNHELD + noise, RUBBLE, "rubble:12", HEADING_SECONDS, noise, "Course");
        }
    }

    @AfterAll
    static void stopRuns() {
        pool.shutdownNow();
    }

    private static void start(String label, Path network, String course, long noise) {
        start(label, network, course, SECONDS, noise);
    }

    /** Queues one run: {@code network} on {@code course} for {@code seconds}, noise seed {@code noise}. */
    private static void start(String label, Path network, String course, int seconds, long noise, String... unloaded) {
        RUNS.put(label, pool.submit(() -> {
            try (SimulatedRoq roq = SimulatedRoq.builder().network(network).course(course).noise(noise)
                    .unload(unloaded).start()) {
                roq.runFor(Duration.ofSeconds(seconds));
                LOG.info("{}: {}", roq.name(), roq.measures());
                return new Walk(roq.measures(), roq.assertThat());
            }
        }));
    }

    private static Walk run(String label) throws Exception {
        return RUNS.get(label).get();
    }

    /** What every run must show; {@code least} m walked, {@code tilt} rad at most. */
    private static void holds(SoftAssertions soft, Walk w, double least, double tilt) {
        holds(soft, w, least, tilt, 0);
    }

    /** The same with up to {@code breakthroughs} cells broken under a loaded foot. */
    private static void holds(SoftAssertions soft, Walk w, double least, double tilt, int breakthroughs) {
        soft.assertThatCode(() -> w.then().noFall().loadedFootBreakthroughsAtMost(breakthroughs).walkedAtLeast(least)
                .trackErrorAtMost(MAX_TRACK).headingErrorAtMost(MAX_HEADING).tiltAtMost(tilt))
                .doesNotThrowAnyException();
    }

    @Test
    void shouldWalkLevelGroundOnItsLine() throws Exception {
        SoftAssertions soft = new SoftAssertions();
        // measured 1.03 and 1.87 m in 40 s (roq-rubble's 5 s of settling included)
        holds(soft, run("roq-walk flat"), 0.8, LEVEL_TILT);
        holds(soft, run("roq-rubble flat"), 1.45, LEVEL_TILT);
        soft.assertAll();
    }

    @Test
    void shouldClimbAndDescendSlopesUpToFifteenDegrees() throws Exception {
        SoftAssertions soft = new SoftAssertions();
        // measured 1.51 m (the built-in course: 1 m of level ground first), 1.03 m (0.6 m of it up the 15° incline)
        // and 2.40 m down, the body levelled by module Posture (without it RoQ tips over going down: below)
        holds(soft, run("roq-rubble slope (built-in, 10 up)"), 1.2, Math.toRadians(10) + SLOPE_TILT);
        holds(soft, run("roq-rubble slope 15 up"), 0.8, Math.toRadians(15) + SLOPE_TILT);
        holds(soft, run(DOWN), 1.9, Math.toRadians(15) + SLOPE_TILT);
        soft.assertAll();
    }

    @Test
    void shouldTipOverGoingDownEighteenDegreesWithModulePostureUnloaded() throws Exception {
        // measured on eight noise seeds going down 15°: without Posture 6 fell and 2 reached 0.37-0.39 rad, so a
        // single 15° run cannot tell. 18°, six noise seeds each: without Posture all six fell (0.70-0.81 rad), with
        // it none (0.43-0.47 rad; the bound 0.55 lies 0.08 above the largest). 20° is past its edge: with Posture 3
        // of 6 fell.
        SoftAssertions soft = new SoftAssertions();
        for (long noise : STEEP_NOISE) {
            Walk levelled = run(STEEP + noise);
            RoqMeasures unlevelled = run(STEEP_UNLEVELLED + noise).measures();
            soft.assertThatCode(() -> levelled.then().noFall().tiltAtMost(0.55)).doesNotThrowAnyException();
            soft.assertThat(unlevelled.fallen()).as(unlevelled + " against " + levelled.measures() + ": fallen")
                    .isTrue();
        }
        soft.assertAll();
    }

    @Test
    void shouldCrossRubbleUpToSixCentimetresOnFiveSeeds() throws Exception {
        SoftAssertions soft = new SoftAssertions();
        List<String> labels = new ArrayList<>(List.of("roq-rubble rubble 2004"));
        for (long seed : SEEDS) {
            labels.add("roq-rubble rubble " + seed);
        }
        // measured 1.73, 1.65, 1.56, 1.77, 1.50 m (seeds 2004, 11, 12, 13, 21): median 1.65, the threshold 21 % below
        for (String label : labels) {
            holds(soft, run(label), 1.3, LEVEL_TILT);
        }
        soft.assertAll();
    }

    @Test
    void shouldCrossFragileCellsBreakingAtMostTwoUnderALoadedFoot() throws Exception {
        SoftAssertions soft = new SoftAssertions();
        // measured 1.75 m (1 crust broken under a loaded foot) and 1.67 m (4 broken by probes, none under a loaded
        // foot here; 1-4 per 100 s crossing on noise seeds 1, 2, 3, 31). None under a loaded foot does not hold yet:
        // a foothold accepted on a crust's edge, partly on the ground beside it, bears the probe's 55 N and later
        // breaks under the three-foot load, more often with the demo's 0.3 m stride (docs/explanation/roq-control.md); 2 a run
        // bounds it until it does
        holds(soft, run("roq-rubble fragile"), 1.35, LEVEL_TILT, 2);
        holds(soft, run("roq-rubble crossing"), 1.3, LEVEL_TILT, 2);
        soft.assertAll();
    }

    @Test
    void shouldStayCloserToItsCourseLineWithModuleCourseThanWithout() throws Exception {
        // measured over 3.0-3.5 m on these eight noise seeds: off the line 0.13-0.30 m with Course (mean 0.23),
        // 0.18-0.91 m without (mean 0.48): 0.48x, and the bound is 0.75x. Run by run the comparison failed on three of them
        // (Course did worse than none on two): the crawl's sideways slip, which Course does not sense, is as large as
        // the heading's drift over 3 m, so only the means compare.
        SoftAssertions soft = new SoftAssertions();
        double held = 0;
        double unheld = 0;
        for (long noise : HEADING_NOISE) {
            Walk with = run(HELD + noise);
            RoqMeasures without = run(UNHELD + noise).measures();
            held += with.measures().trackError() / HEADING_NOISE.length;
            unheld += without.trackError() / HEADING_NOISE.length;
            soft.assertThatCode(() -> with.then().noFall().walkedAtLeast(2.2).trackErrorAtMost(MAX_TRACK))
                    .doesNotThrowAnyException();
        }
        soft.assertThat(held).as("mean off the course line with Course, against without (%.3f m), m", unheld)
                .isLessThan(0.75 * unheld);
        soft.assertAll();
    }
}
