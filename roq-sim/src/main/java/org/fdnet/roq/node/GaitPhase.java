package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import org.fdnet.runtime.Value;

/**
 * The gait's phase, the one value every robot Relation plans by, decoded in one place. On the wire (the Data
 * {@code gait phase}) it is up to five numbers, in this order:
 *
 * <ol>
 *   <li>{@code leg}: the leg about to lift, in the air, or whose foothold is being proved (−1: none, RoQ stands);</li>
 *   <li>{@code inAir}: 1 while that leg's foot is off the ground;</li>
 *   <li>{@code attempt}: a probe attempt — a new positive number for each foothold the gait proves, 0 otherwise;
 *   while it is positive a foothold that gives way under {@code leg} was broken by the probe, on purpose;</li>
 *   <li>{@code unloading}: the leg whose weight is being taken off before it lifts (−1: none);</li>
 *   <li>{@code unloaded}: how much of that leg's share has been taken off so far, 0..1.</li>
 * </ol>
 *
 * The older crawl writes only the first two or three numbers; the missing ones read as none.
 *
 * @param leg       the leg the phase is about, or −1
 * @param inAir     whether that leg's foot is off the ground
 * @param attempt   the probe attempt, 0 when no foothold is being proved
 * @param unloading the leg being unloaded before its lift, or −1
 * @param unloaded  how much of its share is off it, 0..1
 */
public record GaitPhase(int leg, boolean inAir, long attempt, int unloading, double unloaded) {
    /** RoQ standing: no leg named. */
    public static final GaitPhase STANDING = new GaitPhase(-1, false, 0, -1, 0);

    /** Checks the legs and the share; the message names the bad one. */
    public GaitPhase {
        if (leg < -1 || leg >= LEGS) {
            throw new IllegalArgumentException("gait phase leg must be -1.." + (LEGS - 1) + ", was " + leg);
        }
        if (unloading < -1 || unloading >= LEGS) {
            throw new IllegalArgumentException("gait phase unloading leg must be -1.." + (LEGS - 1) + ", was "
                    + unloading);
        }
        if (!(unloaded >= 0 && unloaded <= 1)) {
            throw new IllegalArgumentException("gait phase unloaded share must be 0..1, was " + unloaded);
        }
    }

    /** The phase in {@code v} (2 to 5 numbers), or {@link #STANDING} for null, a short value or numbers out of range. */
    public static GaitPhase of(Value v) {
        if (v == null || v.length() < 2) {
            return STANDING;
        }
        int leg = (int) v.element(0);
        int unloading = v.length() > 3 ? (int) v.element(3) : -1;
        double unloaded = v.length() > 4 ? v.element(4) : 0;
        if (leg < -1 || leg >= LEGS || unloading < -1 || unloading >= LEGS || !(unloaded >= 0 && unloaded <= 1)) {
            return STANDING;
        }
        return new GaitPhase(leg, v.element(1) > 0.5, v.length() > 2 ? (long) v.element(2) : 0, unloading, unloaded);
    }

    /** The five numbers of the wire form. */
    public Value value() {
        return Value.ofDoubles(leg, inAir ? 1 : 0, attempt, unloading, unloaded);
    }

    /** Whether a foothold is being proved: a break under {@link #leg()} now is the probe's. */
    public boolean proving() {
        return attempt > 0 && leg >= 0;
    }

    /** The leg in the air or whose foothold is being proved, else −1. */
    public int upLeg() {
        return inAir || proving() ? leg : -1;
    }
}
