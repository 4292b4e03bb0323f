package org.fdnet.roq.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.Push;
import org.fdnet.roq.sim.RoqGeometry;

/**
 * {@code fdnet bench roq --part push}: for each push direction and each phase of a leg lift, the largest push RoQ
 * survives ({@link PushTrial#largestSurvived}) with the full network beside the same network with Balance and Reflex
 * unloaded, and their ratio. Stepped and deterministic; the bisections run on at most two threads.
 */
final class PushSurvivalBench {
    /** Modules unloaded for the baseline: what the network adds to survive a push. */
    static final String[] UNLOADED = {"Balance", "Reflex"};

    private final NetworkInfo network;
    private final Course course;
    private final long noise;
    private final double[] directions;
    private final double[] offsets;
    private final double resolution;

    PushSurvivalBench(NetworkInfo network, Course course, long noise, double[] directions, double[] offsets,
                      double resolution) {
        this.network = network;
        this.course = course;
        this.noise = noise;
        this.directions = directions.clone();
        this.offsets = offsets.clone();
        this.resolution = resolution;
    }

    /** Runs every bisection, prints the table; returns the smallest full / unloaded ratio. */
    double run() throws Exception {
        System.out.printf(Locale.ROOT, "fdnet bench roq --part push: %s on course %s, noise seed %d, stepped; push %.1f s"
                        + " starting at the first leg lift after %.1f s plus the offset; survived = no fall latched and"
                        + " tilt < %.1f rad over %.1f s after; bisection to %.0f N; baseline: modules %s unloaded%n",
                network.name(), course.name(), noise, PushTrial.DURATION, PushTrial.WARM_UP, PushTrial.TILT_LIMIT,
                PushTrial.SETTLE, resolution, String.join(" and ", UNLOADED));
        PushTrial full = new PushTrial(network, course, noise);
        PushTrial bare = new PushTrial(network, course, noise, UNLOADED);
        ExecutorService pool = Executors.newFixedThreadPool(2);
        List<Future<PushTrial.Limit>> withNetwork = new ArrayList<>();
        List<Future<PushTrial.Limit>> without = new ArrayList<>();
        try {
            for (double d : directions) {
                for (double o : offsets) {
                    withNetwork.add(pool.submit(() -> full.largestSurvived(d, o, resolution)));
                    without.add(pool.submit(() -> bare.largestSurvived(d, o, resolution)));
                }
            }
            System.out.println("direction  offset into swing  full network  Balance+Reflex unloaded  ratio  leg in the air");
            double least = Double.POSITIVE_INFINITY;
            double logSum = 0;
            int k = 0;
            for (double d : directions) {
                for (double o : offsets) {
                    PushTrial.Limit limit = withNetwork.get(k).get();
                    double f = limit.force();
                    double b = without.get(k).get().force();
                    k++;
                    double ratio = b > 0 ? f / b : Double.POSITIVE_INFINITY;
                    least = Math.min(least, ratio);
                    logSum += Math.log(ratio);
                    System.out.printf(Locale.ROOT, "%7.0f°  %15.2f s  %10.0f N%s  %21.0f N%s  %5.2f×  %s%n", d, o, f,
                            f >= Push.MAX_FORCE ? "+" : " ", b, b >= Push.MAX_FORCE ? "+" : " ", ratio,
                            RoqGeometry.LEG_NAMES[limit.leg()]);
                }
            }
            double mean = Math.exp(logSum / k);
            System.out.printf(Locale.ROOT, "ratio full / unloaded: smallest %.2f×, geometric mean %.2f× (target ≥ 1.5×"
                    + " in every row: %s)%n", least, mean, least >= 1.5 ? "met" : "NOT met");
            return least;
        } finally {
            pool.shutdownNow();
        }
    }
}
