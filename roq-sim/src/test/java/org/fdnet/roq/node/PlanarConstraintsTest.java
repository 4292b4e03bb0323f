package org.fdnet.roq.node;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.Test;

class PlanarConstraintsTest {
    private final PlanarConstraints plan = new PlanarConstraints(8);
    private final double[] out = new double[2];

    @Test
    void aWantedPointInsideEveryHalfPlaneIsKept() {
        plan.add(1, 0, 1, 0);
        plan.add(0, 1, 1, 0);
        assertThat(plan.nearest(0.5, -2, out)).isZero();
        assertThat(out).containsExactly(0.5, -2);
    }

    @Test
    void aWantedPointOutsideOneHalfPlaneGoesStraightToItsEdge() {
        plan.add(2, 0, 2, 0); // x ≤ 1, given unnormalised
        plan.add(0, 1, 5, 0);
        plan.nearest(3, 0.25, out);
        assertThat(out[0]).isCloseTo(1, within(1e-12));
        assertThat(out[1]).isCloseTo(0.25, within(1e-12));
    }

    @Test
    void aWantedPointBeyondTwoEdgesGoesToTheirCorner() {
        plan.add(1, 0, 1, 0);
        plan.add(0, 1, 1, 0);
        plan.add(-1, -1, 10, 0);
        plan.nearest(3, 3, out);
        assertThat(out[0]).isCloseTo(1, within(1e-12));
        assertThat(out[1]).isCloseTo(1, within(1e-12));
    }

    @Test
    void theLastRankIsGivenUpWhenNotAllHalfPlanesCanHold() {
        plan.add(1, 0, 1, 0);   // x ≤ 1
        plan.add(0, 1, 0, 1);   // y ≤ 0
        plan.add(-1, 0, -2, 2); // x ≥ 2: contradicts the first
        assertThat(plan.nearest(3, 3, out)).isEqualTo(1);
        assertThat(out[0]).isCloseTo(1, within(1e-12));
        assertThat(out[1]).isCloseTo(0, within(1e-12));
    }

    @Test
    void noPointAtAllLeavesTheWantedOneAndSaysSo() {
        plan.add(1, 0, 1, 0);
        plan.add(-1, 0, -2, 0);
        assertThat(plan.nearest(3, 3, out)).isEqualTo(-1);
        assertThat(out).containsExactly(3, 3);
    }

    @Test
    void aClearedSetConstrainsNothing() {
        plan.add(1, 0, 1, 0);
        plan.clear();
        assertThat(plan.size()).isZero();
        assertThat(plan.nearest(3, 3, out)).isZero();
        assertThat(out).containsExactly(3, 3);
    }
}
