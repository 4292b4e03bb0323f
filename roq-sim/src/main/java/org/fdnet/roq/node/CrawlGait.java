package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.*;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * A crawl gait, the static walk: one leg in the air at a time, in the order hind-right, front-right, hind-left,
 * front-left. Each leg owns a quarter of the {@code cycle} (s, default 5): the body first has time to shift
 * (see {@link KeepBalance}), then the leg swings {@code stride} m (default 0.15) forward, {@code clearance} m
 * (default 0.06) high, while the feet on the ground move backwards under the body at a steady speed. Writes, in
 * Writer order, (0) the feet's centres in the body frame (12 numbers) for a body {@code height} m high (default
 * 0.27) and (1) the gait phase {leg whose quarter it is, 1 while that leg is in the air else 0}. Needs a
 * {@code period}. Its phase only moves while it fires: held, it stops the walk where it is; resumed, it goes on.
 */
public class CrawlGait extends Relation {
    /** hr, fr, hl, fl. */
    static final int[] ORDER = {3, 1, 2, 0};
    private static final double SHIFT = 0.08;
    private static final double SWING = 0.14;

    private final double[] feet = new double[3 * LEGS];
    private final double[] home = new double[3 * LEGS];
    private double cycle;
    private double stride;
    private double clearance;
    private double height;
    private double phase;
    private double lastSeconds = Double.NaN;
    private double maxStep;

    @Override
    protected void init(NodeParameters p) {
        cycle = p.doubleValue("cycle", 5.0);
        stride = p.doubleValue("stride", 0.15);
        clearance = p.doubleValue("clearance", 0.06);
        height = p.doubleValue("height", 0.27);
        if (cycle < 0.5) {
            throw p.invalid("cycle", "must be at least 0.5 s, was " + cycle);
        }
        if (stride < 0 || stride > 0.3) {
            throw p.invalid("stride", "must lie between 0 and 0.3 m, was " + stride);
        }
        if (clearance < 0 || clearance > 0.15) {
            throw p.invalid("clearance", "must lie between 0 and 0.15 m, was " + clearance);
        }
        if (height < 0.15 || height > 0.4) {
            throw p.invalid("height", "must lie between 0.15 and 0.4 m, was " + height);
        }
        maxStep = 4 * p.longValue("period", 10) / 1000.0;
        double[] foot = new double[3];
        for (int leg = 0; leg < LEGS; leg++) {
            footInBody(leg, STANDING_POSE[0], STANDING_POSE[1], STANDING_POSE[2], foot);
            home[3 * leg] = foot[0];
            home[3 * leg + 1] = foot[1];
            home[3 * leg + 2] = -(height - FOOT_RADIUS);
        }
    }

    @Override
    protected void compute(RelationContext c) {
        double now = c.seconds();
        if (!Double.isNaN(lastSeconds)) {
            // a held gait does not fire: its phase waits; after a resume it goes on from there
            phase += Math.min(maxStep, Math.max(0, now - lastSeconds)) / cycle;
            phase -= Math.floor(phase);
        }
        lastSeconds = now;
        int quarter = Math.min(3, (int) (phase * 4));
        boolean inAir = false;
        for (int q = 0; q < 4; q++) {
            int leg = ORDER[q];
            double u = phase - q * 0.25 - SHIFT;
            u -= Math.floor(u);
            double x;
            double lift = 0;
            if (u < SWING) {
                double s = u / SWING;
                x = -stride / 2 + stride * s;
                lift = clearance * Math.sin(Math.PI * s);
                inAir |= q == quarter;
            } else {
                double s = (u - SWING) / (1 - SWING);
                x = stride / 2 - stride * s;
            }
            feet[3 * leg] = home[3 * leg] + x;
            feet[3 * leg + 1] = home[3 * leg + 1];
            feet[3 * leg + 2] = home[3 * leg + 2] + lift;
        }
        c.output(0, Value.ofDoubles(feet));
        if (c.outputCount() > 1) {
            c.output(1, Value.ofDoubles(ORDER[quarter], inAir ? 1 : 0));
        }
    }
}
