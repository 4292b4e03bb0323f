package org.fdnet.roq.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.roq.bridge.CourseMeter;
import org.fdnet.roq.testkit.CourseSpec;
import org.fdnet.roq.testkit.RoqMeasures;

/**
 * {@code fdnet bench roq --part heading}: on a few 6 cm rubble courses ({@link CourseSpec#rubble}), how far RoQ strays
 * off its course line and heading over ~3 m of walking with module Course loaded beside unloaded, on several sensor-
 * noise seeds. One run tells little — over eight noise seeds of one course the drift without Course ranged 0.18–0.91
 * m, and run by run Course did worse than none on two of them — so each course's line is the mean over the noise seeds, and
 * the verdict the ratio of the means. Stepped and deterministic, at most two runs at a time.
 */
final class HeadingDriftBench {
    private final NetworkInfo network;
    private final long[] seeds;
    private final int seconds;
    private final long[] noises;

    HeadingDriftBench(NetworkInfo network, long[] seeds, int seconds, long[] noises) {
        this.network = network;
        this.seeds = seeds.clone();
        this.seconds = seconds;
        this.noises = noises.clone();
    }

    /** Runs both variants on every course and noise seed and prints the table; returns the largest ratio of means. */
    double run() throws Exception {
        System.out.printf(Locale.ROOT, "fdnet bench roq --part heading: %s on 6 cm rubble, %d simulated s per run,"
                        + " %d noise seeds per course, stepped; off the line / heading = largest cycle mean (%.1f s);"
                        + " baseline: module Course unloaded%n", network.name(), seconds, noises.length,
                CourseMeter.WINDOW / 100.0);
        ExecutorService pool = Executors.newFixedThreadPool(2);
        List<Future<MeasuredWalk>> held = new ArrayList<>();
        List<Future<MeasuredWalk>> unheld = new ArrayList<>();
        try {
            for (long seed : seeds) {
                for (long noise : noises) {
                    held.add(pool.submit(() -> MeasuredWalk.of("rubble " + seed + ", noise " + noise + ", with Course",
                            network, CourseSpec.rubble(seed), seconds, noise)));
                    unheld.add(pool.submit(() -> MeasuredWalk.of("rubble " + seed + ", noise " + noise
                            + ", without Course", network, CourseSpec.rubble(seed), seconds, noise, "Course")));
                }
            }
            System.out.println("rubble seed  mean walked with / without  mean off the line with / without (ratio,"
                    + " runs Course did worse)  mean off the heading with / without  fallen with / without");
            double worst = 0;
            for (int k = 0; k < seeds.length; k++) {
                double[] with = new double[3];
                double[] without = new double[3];
                int worse = 0;
                int fellWith = 0;
                int fellWithout = 0;
                for (int n = 0; n < noises.length; n++) {
                    MeasuredWalk heldWalk = held.get(k * noises.length + n).get();
                    MeasuredWalk unheldWalk = unheld.get(k * noises.length + n).get();
                    System.out.println("  " + heldWalk + "\n  " + unheldWalk);
                    RoqMeasures w = heldWalk.measures();
                    RoqMeasures wo = unheldWalk.measures();
                    add(with, w);
                    add(without, wo);
                    worse += w.trackError() > wo.trackError() ? 1 : 0;
                    fellWith += w.fallen() ? 1 : 0;
                    fellWithout += wo.fallen() ? 1 : 0;
                }
                double ratio = with[1] / without[1];
                worst = Math.max(worst, ratio);
                System.out.printf(Locale.ROOT, "%11d  %14.3f / %.3f m  %17.3f / %.3f m (%.2f×, %d of %d)  %19.3f / %.3f"
                                + " rad  %d / %d%n", seeds[k], with[0] / noises.length, without[0] / noises.length,
                        with[1] / noises.length, without[1] / noises.length, ratio, worse, noises.length,
                        with[2] / noises.length, without[2] / noises.length, fellWith, fellWithout);
            }
            System.out.printf(Locale.ROOT, "off the line with Course / without, means over %d noise seeds: at most %.2f×"
                    + " over %d courses%n", noises.length, worst, seeds.length);
            return worst;
        } finally {
            pool.shutdownNow();
        }
    }

    private static void add(double[] sums, RoqMeasures r) {
        sums[0] += r.distance();
        sums[1] += r.trackError();
        sums[2] += r.headingError();
    }
}
