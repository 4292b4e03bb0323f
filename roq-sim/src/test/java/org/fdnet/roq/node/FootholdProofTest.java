package org.fdnet.roq.node;

import static org.assertj.core.api.Assertions.assertThat;

import org.fdnet.roq.node.FootholdProof.Verdict;
import org.junit.jupiter.api.Test;

class FootholdProofTest {
    private static final double DT = 0.01;

    private final FootholdProof proof = new FootholdProof(0.2, 25);

    @Test
    void aFootholdBearingItsFullLoadForTheHoldIsAccepted() {
        proof.start();
        Verdict v = Verdict.PENDING;
        int ticks = 0;
        while (v == Verdict.PENDING && ticks < 100) {
            v = proof.observe(88, 93, true, DT);
            ticks++;
        }
        assertThat(v).isEqualTo(Verdict.ACCEPTED);
        assertThat(ticks * DT).isBetween(0.19, 0.22);
    }

    @Test
    void bearingTheLoadBeforeTheTransferIsCompleteDoesNotCount() {
        proof.start();
        for (int i = 0; i < 50; i++) {
            assertThat(proof.observe(93, 93, false, DT)).isEqualTo(Verdict.PENDING);
        }
    }

    @Test
    void aForceThatCollapsesUnderTheLoadRejectsTheFoothold() {
        proof.start();
        for (int i = 0; i < 10; i++) {
            proof.observe(60, 70, false, DT);
        }
        Verdict v = Verdict.PENDING;
        for (int i = 0; i < 10 && v == Verdict.PENDING; i++) {
            v = proof.observe(3, 70, false, DT);
        }
        assertThat(v).isEqualTo(Verdict.REJECTED);
    }

    @Test
    void theTouchdownsPeakFollowedByALowTargetIsNoCollapse() {
        proof.start();
        proof.observe(75, 5, false, DT); // the impact, while the load is still being moved on
        for (int i = 0; i < 20; i++) {
            assertThat(proof.observe(8, 10 + i, false, DT)).isEqualTo(Verdict.PENDING);
        }
    }
}
