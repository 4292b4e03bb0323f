package org.fdnet.roq.bridge;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.fdnet.roq.sim.FragileCell;
import org.junit.jupiter.api.Test;

/** Whose foot a cell broke under: the foot nearest it, swinging or standing, and whether a standing one had slid. */
class BreakthroughCausesTest {
    /** Two crusts 0.15 × 0.3 m, as on {@code crossing}: cell 0 ahead on the left, cell 1 ahead on the right. */
    private static final List<FragileCell> CELLS = List.of(
            new FragileCell(1.0, 0.35, 0.15, 0.3, 0.03, 40), new FragileCell(1.0, -0.35, 0.15, 0.3, 0.03, 40));
    private static final boolean[] NONE = {false, false};
    private static final boolean[] FIRST = {true, false};
    private static final boolean[] BOTH = {true, true};

    /** Feet fl, fr, hl, hr (x, y), front-left at {@code flX, flY}. */
    private static double[] feet(double flX, double flY, double frX, double frY) {
        return new double[] {flX, flY, frX, frY, 0.4, 0.3, 0.4, -0.3};
    }

    @Test
    void shouldTellABreakUnderTheLegInTheAirFromOneUnderAStandingFoot() {
        BreakthroughCauses causes = new BreakthroughCauses(CELLS);
        causes.sample(feet(0.9, 0.3, 0.7, -0.3), 0, NONE, false); // front-left swinging over cell 0
        causes.sample(feet(0.9, 0.3, 0.7, -0.3), 0, FIRST, false);
        assertThat(causes.swinging()).isEqualTo(1);
        assertThat(causes.standing()).isZero();
        causes.sample(feet(0.9, 0.3, 1.0, -0.3), 3, BOTH, false); // hind-right swinging, front-right stands on cell 1
        assertThat(causes.swinging()).isEqualTo(1);
        assertThat(causes.standing()).isEqualTo(1);
        assertThat(causes.summary()).isEqualTo("under a swinging foot 1, under a standing foot 1, 0 of them slid since set down");
    }

    @Test
    void shouldCountAStandingFootAsSlidWhenItMovedFromWhereItWasSetDown() {
        BreakthroughCauses causes = new BreakthroughCauses(CELLS);
        causes.sample(feet(0.85, 0.2, 0.7, -0.3), 0, NONE, false); // front-left in the air
        causes.sample(feet(0.88, 0.15, 0.7, -0.3), -1, NONE, false); // set down 5.5 cm outside cell 0's inner edge
        causes.sample(feet(0.9, 0.19, 0.7, -0.3), 1, NONE, false); // slid 4.5 cm onto the edge while front-right swings
        causes.sample(feet(0.9, 0.19, 0.7, -0.3), 1, FIRST, false);
        assertThat(causes.standing()).isEqualTo(1);
        assertThat(causes.slid()).isEqualTo(1);
    }

    @Test
    void shouldLeaveABreakUnderTheProbedFootAndOneUnderNoFootApart() {
        BreakthroughCauses causes = new BreakthroughCauses(CELLS);
        causes.sample(feet(1.0, 0.3, 0.5, -0.3), 0, FIRST, true); // front-left's probe broke cell 0: on purpose
        assertThat(causes.probeBroken()).isEqualTo(1);
        assertThat(causes.loaded()).isZero();
        causes.sample(feet(1.0, 0.3, 0.5, -0.3), 0, BOTH, false); // cell 1 broke with no foot within 4 cm of it
        assertThat(causes.swinging() + causes.standing()).isZero();
        assertThat(causes.noFoot()).isEqualTo(1);
        assertThat(causes.loaded()).isEqualTo(1);
        assertThat(causes.summary()).endsWith(", under no foot 1");
    }

    @Test
    void shouldCountABreakUnderAStandingFootDuringAnotherFootsPressAsALoadedFootBreakthrough() {
        BreakthroughCauses causes = new BreakthroughCauses(CELLS);
        causes.sample(feet(1.3, 0.3, 1.0, -0.3), 0, NONE, true); // front-left presses ahead of cell 0; front-right stands on cell 1
        causes.sample(feet(1.3, 0.3, 1.0, -0.3), 0, new boolean[] {false, true}, true);
        assertThat(causes.probeBroken()).as("not under the probed foot").isZero();
        assertThat(causes.standing()).isEqualTo(1);
        assertThat(causes.loaded()).isEqualTo(1);
    }

    @Test
    void shouldLeaveCellsBrokenBeforeMeasuringStartedOut() {
        BreakthroughCauses causes = new BreakthroughCauses(CELLS);
        causes.alreadyBroken(FIRST);
        causes.sample(feet(1.0, 0.3, 1.0, -0.3), -1, BOTH, false); // front-right stands on cell 1 as it breaks
        assertThat(causes.loaded()).as("cell 0 was broken before; cell 1 broke now").isEqualTo(1);
        assertThat(causes.probeBroken()).isZero();
    }
}
