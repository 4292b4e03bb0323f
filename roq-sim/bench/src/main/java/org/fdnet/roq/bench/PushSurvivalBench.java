package org.fdnet.roq.bench;

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
 * survives with the full network beside the same network with Balance and Reflex unloaded, and their ratio, by two
 * definitions measured alike for both: the largest push below which every push of a {@link #SCAN_STEP} N scan is
 * survived ({@link PushTrial#scan}, the headline: it assumes nothing above the first failure) and the
 * bisection's answer ({@link PushTrial#largestSurvived}, which assumes survival falls with force; printed beside it
 * because sideways it does not). Stepped and deterministic; the rows run on at most two threads.
 */
final class PushSurvivalBench {
    /** Modules unloaded for the baseline: what the network adds to survive a push. */
    static final String[] UNLOADED = {"Balance", "Reflex"};
    /** The scan's step, N. */
    static final double SCAN_STEP = 50;

    private final NetworkInfo network;
    private final Course course;
    private final long noise;
    private final double[] directions;
    private final double[] offsets;
    private final double resolution;
    private final boolean wholeScan;

    PushSurvivalBench(NetworkInfo network, Course course, long noise, double[] directions, double[] offsets,
                      double resolution, boolean wholeScan) {
        this.network = network;
        this.course = course;
        this.noise = noise;
        this.directions = directions.clone();
        this.offsets = offsets.clone();
        this.resolution = resolution;
        this.wholeScan = wholeScan;
    }

    /** One set-up's two answers in one row. */
    private record Limits(PushTrial.Scan scan, PushTrial.Limit bisected) {
        static Limits of(PushTrial trial, double direction, double offset, double resolution, boolean whole)
                throws Exception {
            return new Limits(trial.scan(direction, offset, SCAN_STEP, whole),
                    trial.largestSurvived(direction, offset, resolution));
        }

        PushTrial.Limit throughout() {
            return new PushTrial.Limit(scan.throughout(), scan.leg());
        }
    }

    /** Runs every scan and bisection, prints the table; returns the smallest full / unloaded ratio of the scans. */
    double run() throws Exception {
        System.out.printf(Locale.ROOT, "fdnet bench roq --part push: %s on course %s, noise seed %d, stepped; push %.1f s"
                        + " starting at the first leg lift after %.1f s plus the offset; survived = no fall latched and"
                        + " tilt < %.1f rad over %.1f s after; 'every' = the largest push below which every push of a"
                        + " %.0f N scan is survived, 'bisection' = bisection to %.0f N (assumes survival falls with"
                        + " force); baseline: modules %s unloaded%n",
                network.name(), course.name(), noise, PushTrial.DURATION, PushTrial.WARM_UP, PushTrial.TILT_LIMIT,
                PushTrial.SETTLE, SCAN_STEP, resolution, String.join(" and ", UNLOADED));
        PushTrial full = new PushTrial(network, course, noise);
        PushTrial bare = new PushTrial(network, course, noise, UNLOADED);
        ExecutorService pool = Executors.newFixedThreadPool(2);
        List<Future<Limits>> withNetwork = new ArrayList<>();
        List<Future<Limits>> without = new ArrayList<>();
        try {
            for (double d : directions) {
                for (double o : offsets) {
                    withNetwork.add(pool.submit(() -> Limits.of(full, d, o, resolution, wholeScan)));
                    without.add(pool.submit(() -> Limits.of(bare, d, o, resolution, wholeScan)));
                }
            }
            System.out.println("direction  offset   every: full / unloaded   ratio   bisection: full / unloaded   ratio"
                    + "  leg in the air" + (wholeScan ? "  scan survived: full / unloaded" : ""));
            int survivedFull = 0;
            int survivedBare = 0;
            int tried = 0;
            Ratios every = new Ratios();
            Ratios bisected = new Ratios();
            int k = 0;
            for (double d : directions) {
                for (double o : offsets) {
                    Limits f = withNetwork.get(k).get();
                    Limits b = without.get(k).get();
                    k++;
                    System.out.printf(Locale.ROOT, "%7.1f°  %5.2f s  %7s / %-7s  %6.2f×  %11s / %-7s  %6.2f×  %s%s%n", d, o,
                            newtons(f.throughout()), newtons(b.throughout()), every.add(f.throughout(), b.throughout()),
                            newtons(f.bisected()), newtons(b.bisected()), bisected.add(f.bisected(), b.bisected()),
                            RoqGeometry.LEG_NAMES[f.bisected().leg()], wholeScan ? String.format(Locale.ROOT,
                                    "  %13d / %d of %d", f.scan().survived(), b.scan().survived(), f.scan().tried()) : "");
                    survivedFull += f.scan().survived();
                    survivedBare += b.scan().survived();
                    tried += f.scan().tried();
                }
            }
            every.print("every");
            bisected.print("bisection");
            if (wholeScan) {
                System.out.printf(Locale.ROOT, "whole scan (every %.0f N push up to %.0f N): full network survived %d of"
                        + " %d, unloaded %d of %d%n", SCAN_STEP, Push.MAX_FORCE, survivedFull, tried, survivedBare, tried);
            }
            return every.least;
        } finally {
            pool.shutdownNow();
        }
    }

    private static String newtons(PushTrial.Limit limit) {
        return String.format(Locale.ROOT, "%.0f N%s", limit.force(), limit.force() >= Push.MAX_FORCE ? "+" : "");
    }

    /** The ratios of one definition: the smallest, the geometric mean and how many rows fall short. */
    private static final class Ratios {
        private double least = Double.POSITIVE_INFINITY;
        private double logSum;
        private int rows;
        private int belowOne;
        private int belowTarget;

        double add(PushTrial.Limit withNetwork, PushTrial.Limit without) {
            double ratio = without.force() > 0 ? withNetwork.force() / without.force() : Double.POSITIVE_INFINITY;
            least = Math.min(least, ratio);
            logSum += Math.log(ratio);
            rows++;
            belowOne += ratio < 1 ? 1 : 0;
            belowTarget += ratio < 1.5 ? 1 : 0;
            return ratio;
        }

        void print(String definition) {
            System.out.printf(Locale.ROOT, "%s: ratio full / unloaded smallest %.2f×, geometric mean %.2f×; %d of %d rows"
                            + " below 1.5×, %d below 1× (target ≥ 1.5× in every row: %s)%n", definition, least,
                    Math.exp(logSum / rows), belowTarget, rows, belowOne, least >= 1.5 ? "met" : "NOT met");
        }
    }
}
