package org.fdnet.roq.testkit;

import java.util.Locale;

/**
 * Assertions a roboticist writes about a run, from {@link SimulatedRoq#assertThat()}. Each check reads the run's
 * {@link RoqMeasures} at the moment it is called and returns this so checks chain; a failure is an
 * {@link AssertionError} naming the simulated time, the figure, the bound and the whole measure line.
 */
public final class RoqAssertions {
    private final String run;
    private final RoqMeasures m;

    RoqAssertions(String run, RoqMeasures measures) {
        this.run = run;
        this.m = measures;
    }

    /** @return this, after checking RoQ did not fall */
    public RoqAssertions noFall() {
        return check(!m.fallen(), "RoQ fell (largest tilt " + f(m.tilt()) + " rad)");
    }

    /** @return this, after checking RoQ walked at least {@code metres} along the course */
    public RoqAssertions walkedAtLeast(double metres) {
        return check(m.distance() >= metres, "walked " + f(m.distance()) + " m, expected at least " + f(metres) + " m");
    }

    /** @return this, after checking it stayed within {@code metres} of its course line (averaged over a cycle) */
    public RoqAssertions trackErrorAtMost(double metres) {
        return check(m.trackError() <= metres, "track error " + f(m.trackError()) + " m, expected at most "
                + f(metres) + " m");
    }

    /** @return this, after checking its heading stayed within {@code radians} (averaged over a cycle) */
    public RoqAssertions headingErrorAtMost(double radians) {
        return check(m.headingError() <= radians, "heading error " + f(m.headingError()) + " rad, expected at most "
                + f(radians) + " rad");
    }

    /** @return this, after checking no sample tilted more than {@code radians} in roll or pitch */
    public RoqAssertions tiltAtMost(double radians) {
        return check(m.tilt() <= radians, "tilt " + f(m.tilt()) + " rad, expected at most " + f(radians) + " rad");
    }

    /** @return this, after checking no fragile cell broke under a loaded foot */
    public RoqAssertions noLoadedFootBreakthrough() {
        return loadedFootBreakthroughsAtMost(0);
    }

    /** @return this, after checking at most {@code count} fragile cells broke under a loaded foot */
    public RoqAssertions loadedFootBreakthroughsAtMost(int count) {
        return check(m.loadedBreakthroughs() <= count, m.loadedBreakthroughs() + " loaded-foot breakthroughs (under the"
                + " swinging foot " + m.underSwingingFoot() + ", under standing feet " + m.underStandingFoot()
                + "), expected at most " + count);
    }

    /** @return this, after checking the network's stability margin never fell below {@code metres} */
    public RoqAssertions stabilityMarginAtLeast(double metres) {
        if (Double.isNaN(m.smallestStabilityMargin())) {
            throw new AssertionError(prefix() + "the network has no Data named 'margin' to read the stability margin"
                    + " from");
        }
        return check(m.smallestStabilityMargin() >= metres, "smallest stability margin "
                + f(m.smallestStabilityMargin()) + " m, expected at least " + f(metres) + " m");
    }

    private RoqAssertions check(boolean holds, String what) {
        if (!holds) {
            throw new AssertionError(prefix() + what + "\n  " + m);
        }
        return this;
    }

    private String prefix() {
        return String.format(Locale.ROOT, "%s at t = %.2f s: ", run, m.time());
    }

    private static String f(double d) {
        return String.format(Locale.ROOT, "%.3f", d);
    }
}
