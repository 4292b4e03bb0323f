package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Keep balance: reads the gait's feet (12 numbers, body frame) and its phase {leg about to swing or swinging,
 * in the air}, and shifts the body over the support triangle of the three other feet — towards its centroid,
 * which is {@code margin} m (default 0.05) or more inside every edge on RoQ's stance — smoothly, with a time
 * constant {@code tau} s (default 0.25). Writes the shift as an offset to add to every foot (12 numbers:
 * −dx, −dy, 0 per foot) and reports the stability margin: the centre of mass's distance to the nearest edge of
 * the support triangle (negative outside).
 */
public class KeepBalance extends Relation {
    private final double[] offset = new double[3 * LEGS];
    private double tau;
    private double dx;
    private double dy;
    private double last = Double.NaN;
    private double margin;

    @Override
    protected void init(NodeParameters p) {
        tau = p.doubleValue("tau", 0.25);
        margin = p.doubleValue("margin", 0.05);
        if (tau <= 0) {
            throw p.invalid("tau", "must be more than 0 s, was " + tau);
        }
    }

    @Override
    protected void compute(RelationContext c) {
        Value feet = c.input(0);
        Value phase = c.input(1);
        if (feet == null || phase == null || feet.length() != 3 * LEGS || phase.length() < 1) {
            return;
        }
        int lifted = (int) phase.element(0);
        double cx = 0;
        double cy = 0;
        double[] px = new double[3];
        double[] py = new double[3];
        int k = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            if (leg != lifted) {
                px[k] = feet.element(3 * leg);
                py[k] = feet.element(3 * leg + 1);
                cx += px[k] / 3;
                cy += py[k] / 3;
                k++;
            }
        }
        double now = c.seconds();
        double dt = Double.isNaN(last) ? 0 : Math.max(0, now - last);
        last = now;
        double a = 1 - Math.exp(-dt / tau);
        dx += (cx - dx) * a;
        dy += (cy - dy) * a;
        for (int leg = 0; leg < LEGS; leg++) {
            offset[3 * leg] = -dx;
            offset[3 * leg + 1] = -dy;
            offset[3 * leg + 2] = 0;
        }
        c.outputAll(Value.ofDoubles(offset));
        double m = SupportTriangle.margin(px, py, dx, dy);
        c.report(String.format(java.util.Locale.ROOT, "margin %.3f m%s", m, m < margin ? " (below " + margin + ")" : ""));
    }
}
