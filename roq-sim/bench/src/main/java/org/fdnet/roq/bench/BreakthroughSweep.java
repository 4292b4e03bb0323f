package org.fdnet.roq.bench;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.roq.bridge.BreakthroughCauses;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.testkit.RoqMeasures;
import org.fdnet.roq.testkit.SimulatedRoq;

/**
 * {@code fdnet bench roq --part breakthroughs}: a course walked on many sensor-noise seeds, stepped, and how many
 * fragile cells broke under a loaded foot ({@link RoqMeasures#loadedBreakthroughs()}) against under a probe, how far
 * RoQ walked, how far it strayed and whether it fell. One run says little — on {@code crossing} the count moves by
 * 0–3 from one noise seed to the next — so it is the sum over the seeds that compares. Baseline, over the same seeds:
 * the network with module Probing unloaded (every crust stepped on then breaks under a loaded foot), or another
 * network when one is given (the crawl a new gait replaces, beside it). At most two runs at a time; a line per run as
 * it ends.
 */
final class BreakthroughSweep {
    private final NetworkInfo network;
    private final Course course;
    private final long[] noises;
    private final int seconds;
    /** Modules unloaded in every run (the baseline unloads Probing as well). */
    private final String[] unloaded;
    /** The baseline's sum, once {@link #run()} has run. */
    private Sum baseline;
    /** The baseline's network, or null for this network with Probing unloaded. */
    private final NetworkInfo baselineNetwork;

    BreakthroughSweep(NetworkInfo network, Course course, long[] noises, int seconds, String... unloaded) {
        this(network, null, course, noises, seconds, unloaded);
    }

    /** A sweep whose baseline is {@code baselineNetwork} as it is (null: {@code network} with Probing unloaded). */
    BreakthroughSweep(NetworkInfo network, NetworkInfo baselineNetwork, Course course, long[] noises, int seconds,
                      String... unloaded) {
        this.network = network;
        this.baselineNetwork = baselineNetwork;
        this.course = course;
        this.noises = noises.clone();
        this.seconds = seconds;
        this.unloaded = unloaded.clone();
    }

    /** Sums of one variant's runs. */
    record Sum(int runs, int loaded, int probeBroken, int withNone, int fallen, double walked, double leastWalked,
               double track, double heading, int swinging, int standing, int slid, double seconds, long slack,
               long strained) {
        static Sum of(List<MeasuredWalk> walks, double seconds) {
            long slack = walks.stream().mapToLong(MeasuredWalk::slackTicks).min().orElse(-1) < 0 ? -1
                    : walks.stream().mapToLong(MeasuredWalk::slackTicks).sum();
            int swinging = 0;
            int standing = 0;
            int slid = 0;
            int loaded = 0;
            int probe = 0;
            int none = 0;
            int fallen = 0;
            double walked = 0;
            double least = Double.POSITIVE_INFINITY;
            double track = 0;
            double heading = 0;
            for (MeasuredWalk w : walks) {
                RoqMeasures r = w.measures();
                loaded += r.loadedBreakthroughs();
                swinging += r.underSwingingFoot();
                standing += r.underStandingFoot();
                slid += r.slidSinceSetDown();
                probe += r.probeBroken();
                none += r.loadedBreakthroughs() == 0 ? 1 : 0;
                fallen += r.fallen() ? 1 : 0;
                walked += r.distance();
                least = Math.min(least, r.distance());
                track = Math.max(track, r.trackError());
                heading = Math.max(heading, r.headingError());
            }
            return new Sum(walks.size(), loaded, probe, none, fallen, walked / walks.size(), least, track, heading,
                    swinging, standing, slid, seconds, slack,
                    walks.stream().mapToLong(MeasuredWalk::strainedTicks).sum());
        }

        String line(String label) {
            return String.format(Locale.ROOT, "%s: %d loaded-foot breakthroughs over %d runs (%d runs with none; under a"
                            + " swinging foot %d, under a standing foot %d, of which slid %.0f cm or more since set down"
                            + " %d), %d cells broken by probes, %d fallen; walked %.3f m on average (least %.3f); off the"
                            + " line at most %.3f m, off the heading at most %.3f rad; mean speed %.1f cm/s%s; a joint at"
                            + " its torque limit %.0f %% of the time", label,
                    loaded, runs, withNone, swinging, standing, BreakthroughCauses.SLID * 100, slid, probeBroken, fallen,
                    walked, leastWalked, track, heading, walked / seconds * 100,
                    slack < 0 ? "" : String.format(Locale.ROOT, "; %d stance ticks below the least sole force", slack),
                    runs == 0 ? 0.0 : 100.0 * strained * SimulatedRoq.STEP.toMillis() / (runs * seconds * 1000));
        }
    }

    /** Runs both variants on every seed, prints each run and the two sums; returns the network's. */
    Sum run() throws Exception {
        System.out.printf(Locale.ROOT, "fdnet bench roq --part breakthroughs: %s%s on %s, %d simulated s per run, %d"
                        + " noise seeds, stepped, two at a time; baseline: %s%n", network.name(),
                unloaded.length == 0 ? "" : " with " + String.join(", ", unloaded) + " unloaded", course.name(), seconds,
                noises.length, baselineNetwork == null ? "module Probing unloaded" : baselineNetwork.name());
        String[] withoutProbing = Stream.concat(Arrays.stream(unloaded), Stream.of("Probing")).distinct()
                .toArray(String[]::new);
        ExecutorService pool = Executors.newFixedThreadPool(2);
        List<Future<MeasuredWalk>> probed = new ArrayList<>();
        List<Future<MeasuredWalk>> unprobed = new ArrayList<>();
        try {
            for (long noise : noises) {
                probed.add(pool.submit(() -> MeasuredWalk.of("noise " + noise, network, course, seconds, noise,
                        unloaded)));
            }
            for (long noise : noises) {
                unprobed.add(pool.submit(() -> baselineNetwork == null
                        ? MeasuredWalk.of("noise " + noise + ", Probing unloaded", network, course, seconds, noise,
                                withoutProbing)
                        : MeasuredWalk.of("noise " + noise + ", " + baselineNetwork.name(), baselineNetwork, course,
                                seconds, noise)));
            }
            List<MeasuredWalk> with = collect(probed);
            List<MeasuredWalk> without = collect(unprobed);
            Sum sum = Sum.of(with, seconds);
            System.out.println(sum.line("with the network as it is"));
            baseline = Sum.of(without, seconds);
            System.out.println(baseline.line(baselineNetwork == null ? "baseline, module Probing unloaded"
                    : "baseline, " + baselineNetwork.name()));
            return sum;
        } finally {
            pool.shutdownNow();
        }
    }

    /** The baseline's sum (module Probing unloaded) of the last {@link #run()}; null before. */
    Sum baseline() {
        return baseline;
    }

    private static List<MeasuredWalk> collect(List<Future<MeasuredWalk>> futures) throws Exception {
        List<MeasuredWalk> runs = new ArrayList<>();
        for (Future<MeasuredWalk> f : futures) {
            MeasuredWalk r = f.get();
            System.out.println("  " + r);
            runs.add(r);
        }
        return runs;
    }
}
