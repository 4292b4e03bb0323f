package org.fdnet.roq.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.roq.bridge.CourseMeter;
import org.fdnet.roq.bridge.CourseRun;

/**
 * {@code fdnet bench roq --part heading}: on a few 6 cm rubble courses ({@link CourseRun#rubble}), how far RoQ strays
 * off its course line and heading over ~2 m of walking with module Course loaded beside unloaded. Stepped and
 * deterministic (seeded sensor noise), at most two runs at a time.
 */
final class HeadingDriftBench {
    private final NetworkInfo network;
    private final long[] seeds;
    private final int seconds;
    private final long noise;

    HeadingDriftBench(NetworkInfo network, long[] seeds, int seconds, long noise) {
        this.network = network;
        this.seeds = seeds.clone();
        this.seconds = seconds;
        this.noise = noise;
    }

    /** Runs both variants on every seed and prints the table; returns the largest with / without ratio off the line. */
    double run() throws Exception {
        System.out.printf(Locale.ROOT, "fdnet bench roq --part heading: %s on 6 cm rubble, %d simulated s per run,"
                        + " noise seed %d, stepped; off the line / heading = largest cycle mean (%.1f s); baseline:"
                        + " module Course unloaded%n", network.name(), seconds, noise, CourseMeter.WINDOW / 100.0);
        ExecutorService pool = Executors.newFixedThreadPool(2);
        List<Future<CourseRun>> held = new ArrayList<>();
        List<Future<CourseRun>> unheld = new ArrayList<>();
        try {
            for (long seed : seeds) {
                held.add(pool.submit(() -> CourseRun.of("with Course", network, CourseRun.rubble(seed), seconds, noise)));
                unheld.add(pool.submit(() -> CourseRun.of("without Course", network, CourseRun.rubble(seed), seconds,
                        noise, "Course")));
            }
            System.out.println("rubble seed  walked with / without  off the line with / without  off the heading"
                    + " with / without  heading at the end with / without  fallen with / without");
            double worst = 0;
            for (int k = 0; k < seeds.length; k++) {
                CourseRun w = held.get(k).get();
                CourseRun wo = unheld.get(k).get();
                worst = Math.max(worst, w.trackError() / wo.trackError());
                System.out.printf(Locale.ROOT, "%11d  %9.3f / %.3f m  %15.3f / %.3f m  %17.3f / %.3f rad  %20.3f / %.3f rad"
                                + "  %s / %s%n", seeds[k], w.distance(), wo.distance(), w.trackError(), wo.trackError(),
                        w.headingError(), wo.headingError(), w.finalHeading(), wo.finalHeading(), w.fallen(),
                        wo.fallen());
            }
            System.out.printf(Locale.ROOT, "off the line with Course / without: at most %.2f× over %d seeds%n", worst,
                    seeds.length);
            return worst;
        } finally {
            pool.shutdownNow();
        }
    }
}
