package org.fdnet.roq.bridge;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import java.util.List;
import org.fdnet.roq.sim.FragileCell;

/**
 * Which fragile cells a probe broke on purpose and, for the others — the loaded-foot breakthroughs — whose foot they
 * were under, by ground truth (for measuring, never for control). Every cell that breaks is matched to the foot nearest
 * its footprint (within {@link #REACH} m). It is the <b>probe's</b> only when a probe presses and that foot is the
 * probed one; any other break is a loaded-foot breakthrough, told
 * <ul>
 *   <li><b>under a swinging foot</b> — the leg the gait phase has in the air (swinging, not pressing): a foot driven
 *   along the ground or against a crust's face on its way forward;</li>
 *   <li><b>under a standing foot</b> — also while another foot's probe presses (the press and the lean that goes with
 *   it shift the weight between the standing feet) — and of those, the ones whose foot had <b>slid</b> at least
 *   {@link #SLID} m since the gait last set it down: the probe tested another spot than the one that broke;</li>
 *   <li><b>under no foot</b> — none within {@link #REACH} m of the cell (the body, a shank).</li>
 * </ul>
 *
 * <pre>
 *   every sample: feet (world x, y), gait phase {leg, in the air, probe attempt}
 *       └─▶ a leg coming down: where its foot was set down
 *   a cell newly broken ─▶ nearest foot ─▶ the probed one while it presses: the probe's
 *                                       └▶ otherwise: swinging / standing (slid or not) / none
 * </pre>
 */
public final class BreakthroughCauses {
    /** How far from a cell's footprint a foot's centre may be and still stand on it, m (the foot's 3 cm radius + 1 cm). */
    static final double REACH = 0.04;
    /** How far a standing foot must have moved since it was set down to count as slid, m. */
    public static final double SLID = 0.02;

    private final List<FragileCell> cells;
    private final boolean[] known;
    private final double[] setDown = new double[2 * LEGS];
    private final boolean[] setDownKnown = new boolean[LEGS];
    private int upLeg = -1;
    private int probeBroken;
    private int swinging;
    private int standing;
    private int slid;
    private int noFoot;

    /** Tells the breaks of {@code cells} (the course's fragile cells, in their order). */
    public BreakthroughCauses(List<FragileCell> cells) {
        this.cells = List.copyOf(cells);
        this.known = new boolean[cells.size()];
    }

    /** Whether there are cells to tell (a course without fragile cells has no breaks). */
    public boolean hasCells() {
        return !cells.isEmpty();
    }

    /** Leaves the cells {@code broken} already (when measuring starts) out of every count. */
    public void alreadyBroken(boolean[] broken) {
        for (int i = 0; i < known.length; i++) {
            known[i] |= broken[i];
        }
    }

    /**
     * One sample: {@code feet} the feet's world (x, y), 8 numbers; {@code upLeg} the leg the gait phase has in the
     * air or probing (−1: all four down); {@code broken} whether each cell is broken now; {@code probing} whether
     * {@code upLeg}'s probe presses now (a new break under that foot is then the probe's).
     */
    public void sample(double[] feet, int upLeg, boolean[] broken, boolean probing) {
        if (this.upLeg >= 0 && this.upLeg != upLeg) {
            setDown[2 * this.upLeg] = feet[2 * this.upLeg];
            setDown[2 * this.upLeg + 1] = feet[2 * this.upLeg + 1];
            setDownKnown[this.upLeg] = true;
        }
        this.upLeg = upLeg;
        for (int i = 0; i < known.length; i++) {
            if (broken[i] && !known[i]) {
                known[i] = true;
                tell(cells.get(i), feet, upLeg, probing);
            }
        }
    }

    private void tell(FragileCell cell, double[] feet, int upLeg, boolean probing) {
        int leg = -1;
        double nearest = REACH;
        for (int l = 0; l < LEGS; l++) {
            double d = cell.distanceOutside(feet[2 * l], feet[2 * l + 1]);
            if (d <= nearest) {
                nearest = d;
                leg = l;
            }
        }
        if (probing && leg == upLeg && leg >= 0) {
            probeBroken++;
        } else if (leg < 0) {
            noFoot++;
        } else if (leg == upLeg) {
            swinging++;
        } else {
            standing++;
            if (setDownKnown[leg] && Math.hypot(feet[2 * leg] - setDown[2 * leg],
                    feet[2 * leg + 1] - setDown[2 * leg + 1]) >= SLID) {
                slid++;
            }
        }
    }

    /** Cells broken under the probed foot while its probe pressed, on purpose. */
    public int probeBroken() {
        return probeBroken;
    }

    /** Every other break: the loaded-foot breakthroughs, under any foot or none. */
    public int loaded() {
        return swinging + standing + noFoot;
    }

    /** Loaded-foot breakthroughs under the foot of the leg in the air. */
    public int swinging() {
        return swinging;
    }

    /** Loaded-foot breakthroughs under a standing foot. */
    public int standing() {
        return standing;
    }

    /** Of {@link #standing()}, those whose foot had slid at least {@link #SLID} m since it was set down. */
    public int slid() {
        return slid;
    }

    /** Loaded-foot breakthroughs with no foot within {@link #REACH} m of the cell. */
    public int noFoot() {
        return noFoot;
    }

    /** "under a swinging foot S, under a standing foot T, D of them slid since set down[, under no foot N]". */
    public String summary() {
        return "under a swinging foot " + swinging + ", under a standing foot " + standing + ", " + slid
                + " of them slid since set down" + (noFoot > 0 ? ", under no foot " + noFoot : "");
    }
}
