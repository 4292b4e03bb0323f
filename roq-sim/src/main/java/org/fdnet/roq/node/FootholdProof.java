package org.fdnet.roq.node;

/**
 * The probe protocol of the weight-transfer crawl: a foothold is proved by moving onto it the load it will carry
 * while the next leg swings. From touchdown the foot's sole force is watched; the foothold is <b>accepted</b> once
 * the foot has borne at least {@value #BORNE} of its target load (the distribution's share for it with the next leg
 * unloaded) for {@code hold} s without interruption — longer than a fragile cell bears a load above its strength — and
 * <b>rejected</b> when the force collapses: once the foot bore {@value #BEARING} of a target of at least {@code firm}
 * N, its force falls below {@value #COLLAPSE} of the target for {@value #COLLAPSE_TIME} s: the ground gave way. (The
 * force peaks at touchdown above what the foot carries after; only the target tells a collapse.)
 */
final class FootholdProof {
    /** The part of the target load the foot must bear to count as bearing it. */
    static final double BORNE = 0.85;
    /** The part of the target a foot must have borne before its force can collapse. */
    static final double BEARING = 0.7;
    /** The part of the target below which the force counts as collapsed. */
    static final double COLLAPSE = 0.35;
    /** How long it must stay collapsed, s. */
    static final double COLLAPSE_TIME = 0.05;

    enum Verdict { PENDING, ACCEPTED, REJECTED }

    private final double hold;
    private final double firm;
    private double peak;
    private boolean bearing;
    private double borne;
    private double collapsed;
    private Verdict verdict = Verdict.PENDING;

    FootholdProof(double hold, double firm) {
        this.hold = hold;
        this.firm = firm;
    }

    /** A new foothold: nothing borne yet. */
    void start() {
        peak = 0;
        bearing = false;
        borne = 0;
        collapsed = 0;
        verdict = Verdict.PENDING;
    }

    /**
     * One reading, {@code dt} s after the last: the foot bears {@code force} N, its target is {@code target} N, and
     * {@code full} whether the transfer has reached the full target (only then does bearing it count).
     */
    Verdict observe(double force, double target, boolean full, double dt) {
        if (verdict != Verdict.PENDING) {
            return verdict;
        }
        peak = Math.max(peak, force);
        bearing |= target >= firm && force >= BEARING * target;
        if (bearing && target >= firm && force < COLLAPSE * target) {
            collapsed += dt;
            if (collapsed >= COLLAPSE_TIME) {
                verdict = Verdict.REJECTED;
            }
            return verdict;
        }
        collapsed = 0;
        if (full && force >= BORNE * target) {
            borne += dt;
            if (borne >= hold) {
                verdict = Verdict.ACCEPTED;
            }
        } else {
            borne = 0;
        }
        return verdict;
    }

    /** The most the foot bore so far, N. */
    double peak() {
        return peak;
    }
}
