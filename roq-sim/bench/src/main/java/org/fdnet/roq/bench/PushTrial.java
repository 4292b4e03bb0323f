package org.fdnet.roq.bench;

import java.time.Duration;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.Push;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.testkit.SimulatedRoq;
import org.fdnet.runtime.Value;

/**
 * One stepped, deterministic push trial on a {@link SimulatedRoq}: RoQ walks {@code network} (with some modules
 * unloaded) on a course with seeded sensor noise; at the first leg lift after {@link #WARM_UP} s, plus {@code offset} s into the swing, the body
 * is pushed with {@code force} N for {@link #DURATION} s along {@code direction}; then it walks {@link #SETTLE} s
 * more. It survived when FallDetector's latch ({@code fallen}) stayed false and the sensed tilt stayed under
 * {@link #TILT_LIMIT} rad, FallDetector's limit in the RoQ networks.
 */
final class PushTrial {
    /** Seconds walked before the push's leg lift is looked for: one crawl cycle and a bit. */
    static final double WARM_UP = 5.5;
    /** Seconds walked after the push ends. */
    static final double SETTLE = 3.0;
    /** How long each push lasts, s. */
    static final double DURATION = 0.2;
    /** Tilt at which RoQ counts as fallen, rad (FallDetector's limit in the RoQ networks). */
    static final double TILT_LIMIT = 0.6;
    /** The lift is looked for tick by tick, so the push starts where the bench says. */
    private static final Duration TICK = Duration.ofMillis(1);
    /** The tilt after the push is sampled every 10 ms. */
    private static final Duration SAMPLE = Duration.ofMillis(10);

    private final NetworkInfo network;
    private final Course course;
    private final long noise;
    private final String[] unloaded;

    /** A trial set-up: {@code unloaded} modules are unloaded right after the network starts. */
    PushTrial(NetworkInfo network, Course course, long noise, String... unloaded) {
        this.network = network;
        this.course = course;
        this.noise = noise;
        this.unloaded = unloaded.clone();
    }

    /**
     * What one push did.
     *
     * @param survived  no fall latched and tilt under the limit
     * @param tilt      largest sensed |roll| or |pitch| from the push on, rad
     * @param pushStart simulated time the push began, s
     * @param leg       the leg in the air when it began
     */
    record Outcome(boolean survived, double tilt, double pushStart, int leg) {
    }

    /** Runs one trial. */
    Outcome run(double force, double direction, double offset) {
        try (SimulatedRoq roq = SimulatedRoq.builder().network(network).course(course).noise(noise).unload(unloaded)
                .start()) {
            boolean wasInAir = true;
            int leg = -1;
            double lift = -1;
            while (lift < 0) {
                roq.advance(TICK);
                Value p = roq.network().value("gait phase");
                boolean inAir = p != null && p.length() >= 2 && p.element(1) > 0;
                double now = roq.snapshot().tick() / 1000.0;
                if (inAir && !wasInAir && now >= WARM_UP) {
                    lift = now;
                    leg = (int) p.element(0);
                }
                wasInAir = inAir;
                if (now > WARM_UP + 10) {
                    throw new IllegalStateException("no leg lifted within 10 s after " + WARM_UP + " s");
                }
            }
            double start = lift + offset;
            roq.push(new Push(start, DURATION, force, direction));
            double tilt = 0;
            int ticks = (int) Math.round((offset + DURATION + SETTLE) * 1000);
            for (int t = 0; t < ticks; t += 10) {
                roq.advance(SAMPLE);
                SensorSnapshot s = roq.snapshot();
                tilt = Math.max(tilt, Math.max(Math.abs(s.roll()), Math.abs(s.pitch())));
            }
            Value fallen = roq.network().value("fallen");
            boolean fell = fallen != null && fallen.asBoolean();
            return new Outcome(!fell && tilt < TILT_LIMIT, tilt, start, leg);
        }
    }

    /**
     * The largest push (N, to {@code resolution}) this set-up survives in {@code direction} at {@code offset} s into
     * the swing, by bisection between a push it survives (0 N, no push) and the first of 100, 200, 400 … N it does
     * not. Assumes survival falls with force (what bisection can find). Returns {@link Push#MAX_FORCE} when even that
     * is survived.
     */
    Limit largestSurvived(double direction, double offset, double resolution) throws Exception {
        double lo = 0;
        double hi = 100;
        Outcome last = run(hi, direction, offset);
        while (last.survived()) {
            lo = hi;
            if (hi >= Push.MAX_FORCE) {
                return new Limit(Push.MAX_FORCE, last.leg());
            }
            hi = Math.min(Push.MAX_FORCE, hi * 2);
            last = run(hi, direction, offset);
        }
        while (hi - lo > resolution) {
            double mid = (lo + hi) / 2;
            if (run(mid, direction, offset).survived()) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return new Limit(lo, last.leg());
    }

    /**
     * The largest push (N) such that this set-up survives it and every push below it in steps of {@code step} N:
     * {@code step}, 2 {@code step} … until the first one it does not survive (or {@link Push#MAX_FORCE}), and, when
     * {@code whole}, the scan goes on to {@link Push#MAX_FORCE} counting every push survived. Unlike
     * {@link #largestSurvived} it assumes nothing about forces above the first failure; sideways, where a strong
     * push slides RoQ across the floor, survival does not fall with force (a row survives 1300 N after failing at
     * 750 N) and a bisection's answer there depends on where its halvings happen to land — there how many of the
     * throws RoQ lands from says more than where the first failure falls.
     */
    Scan scan(double direction, double offset, double step, boolean whole) throws Exception {
        return scan(force -> run(force, direction, offset), step, whole);
    }

    /** One push of {@code force} N and what it did. */
    @FunctionalInterface
    interface Pushing {
        Outcome push(double force) throws Exception;
    }

    /** The scan of {@link #scan(double, double, double, boolean)} over any {@code pushing}. */
    static Scan scan(Pushing pushing, double step, boolean whole) throws Exception {
        double throughout = 0;
        boolean failed = false;
        int survived = 0;
        int tried = 0;
        int leg = -1;
        for (double force = step; force <= Push.MAX_FORCE && (whole || !failed); force += step) {
            Outcome o = pushing.push(force);
            leg = o.leg();
            tried++;
            if (o.survived()) {
                survived++;
                throughout = failed ? throughout : force;
            } else {
                failed = true;
            }
        }
        return new Scan(throughout, survived, tried, leg);
    }

    /**
     * A scan's answer.
     *
     * @param throughout the largest push below which every push of the scan was survived, N
     * @param survived   pushes of the scan survived
     * @param tried      pushes of the scan tried
     * @param leg        the leg in the air when the last push began
     */
    record Scan(double throughout, int survived, int tried, int leg) {
    }

    /**
     * A bisection's or a scan's answer.
     *
     * @param force the largest push survived, N
     * @param leg   the leg in the air when the (last) push began (0..3: front left, front right, hind left, hind right)
     */
    record Limit(double force, int leg) {
    }
}
