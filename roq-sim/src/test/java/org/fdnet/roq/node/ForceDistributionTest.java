package org.fdnet.roq.node;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

class ForceDistributionTest {
    private static final double W = 186;
    /** A rectangle of feet a little off square, fl, fr, hl, hr. */
    private static final double[] X = {0.32, 0.30, -0.29, -0.31};
    private static final double[] Y = {0.30, -0.31, 0.28, -0.30};
    private static final boolean[] ALL = {true, true, true, true};

    private final ForceDistribution distribution = new ForceDistribution();
    private final double[] f = new double[4];

    @Test
    void fourFeetCarryTheWeightWhereItComesDownNearestToAnEvenShare() {
        distribution.distribute(X, Y, ALL, 0.03, 0.02, W, 15, -1, 0, f);
        assertStatics(f, 0.03, 0.02);
        for (double force : f) {
            assertThat(force).isBetween(30.0, 65.0);
        }
    }

    @Test
    void theTwistIsTheOneModeTheStaticsLeaveFree() {
        distribution.distribute(X, Y, ALL, 0, 0, W, 0, -1, 0, f);
        double[] t = distribution.twist();
        double sum = 0;
        double mx = 0;
        double my = 0;
        for (int leg = 0; leg < 4; leg++) {
            sum += t[leg];
            mx += t[leg] * X[leg];
            my += t[leg] * Y[leg];
        }
        assertThat(sum).isCloseTo(0, within(1e-9));
        assertThat(mx).isCloseTo(0, within(1e-9));
        assertThat(my).isCloseTo(0, within(1e-9));
        assertThat(t[0] * t[3]).as("diagonal partners move together").isPositive();
        assertThat(t[0] * t[1]).as("neighbours move against each other").isNegative();
    }

    @Test
    void aLegFullyUnloadedCarriesNothingAndTheOtherThreeTheWeightAtTheirBarycentricShares() {
        // the weight over the triangle fl, fr, hl, well inside it
        double cx = (X[0] + X[1] + X[2]) / 3;
        double cy = (Y[0] + Y[1] + Y[2]) / 3;
        distribution.distribute(X, Y, ALL, cx, cy, W, 15, 3, 1, f);
        assertThat(f[3]).isCloseTo(0, within(1e-9));
        assertStatics(f, cx, cy);
        assertThat(f[0]).isCloseTo(W / 3, within(1e-6));
    }

    @Test
    void halfUnloadedIsHalfWayBetweenTheFourFootAndTheThreeFootShares() {
        double cx = 0.1;
        double cy = 0.05;
        double[] four = new double[4];
        double[] three = new double[4];
        distribution.distribute(X, Y, ALL, cx, cy, W, 0, -1, 0, four);
        distribution.distribute(X, Y, ALL, cx, cy, W, 0, 3, 1, three);
        distribution.distribute(X, Y, ALL, cx, cy, W, 0, 3, 0.5, f);
        for (int leg = 0; leg < 4; leg++) {
            assertThat(f[leg]).isCloseTo((four[leg] + three[leg]) / 2, within(1e-9));
        }
        assertStatics(f, cx, cy);
    }

    @Test
    void everyFootOnTheGroundIsAskedForAtLeastTheLeastLoad() {
        // the weight near the fl-hr diagonal leaves fr and hl next to nothing in the even share
        distribution.distribute(X, Y, ALL, 0.2, 0.2, W, 20, -1, 0, f);
        for (double force : f) {
            assertThat(force).isGreaterThanOrEqualTo(20);
        }
    }

    @Test
    void aFootInTheAirIsAskedForNothingAndTheThreeOnTheGroundCarryAll() {
        boolean[] down = {true, false, true, true};
        double cx = (X[0] + X[2] + X[3]) / 3;
        double cy = (Y[0] + Y[2] + Y[3]) / 3;
        distribution.distribute(X, Y, down, cx, cy, W, 15, -1, 0, f);
        assertThat(f[1]).isEqualTo(-1);
        assertThat(f[0] + f[2] + f[3]).isCloseTo(W, within(1e-6));
        assertThat(distribution.twist()).isNull();
    }

    private static void assertStatics(double[] f, double cx, double cy) {
        double sum = 0;
        double mx = 0;
        double my = 0;
        for (int leg = 0; leg < 4; leg++) {
            double force = Math.max(0, f[leg]);
            sum += force;
            mx += force * X[leg];
            my += force * Y[leg];
        }
        assertThat(sum).isCloseTo(W, within(1e-6));
        assertThat(mx / sum).isCloseTo(cx, within(1e-6));
        assertThat(my / sum).isCloseTo(cy, within(1e-6));
    }
}
