package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.*;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * The wish to stand: writes the feet's centres in the body frame (12 numbers) for a body {@code height} m above
 * the ground (default: the standing pose's height), each foot where the standing pose puts it in x and y.
 * It moves from the standing pose's height to {@code height} over {@code ramp} s (default 1) of network time,
 * so give it a {@code period} to be heard while it moves.
 */
public class StandPosture extends Relation {
    private final double[] feet = new double[3 * LEGS];
    private double height;
    private double ramp;
    private double startHeight;

    @Override
    protected void init(NodeParameters p) {
        startHeight = standingHeight();
        height = p.doubleValue("height", startHeight);
        if (height < 0.10 || height > 0.55) {
            throw p.invalid("height", "must lie between 0.10 and 0.55 m (what the legs reach), was " + height);
        }
        ramp = p.doubleValue("ramp", 1.0);
        if (ramp < 0) {
            throw p.invalid("ramp", "must be 0 s or more, was " + ramp);
        }
        double[] foot = new double[3];
        for (int leg = 0; leg < LEGS; leg++) {
            footInBody(leg, STANDING_POSE[0], STANDING_POSE[1], STANDING_POSE[2], foot);
            feet[3 * leg] = foot[0];
            feet[3 * leg + 1] = foot[1];
        }
    }

    @Override
    protected void compute(RelationContext c) {
        double f = ramp == 0 ? 1 : Math.min(1, c.seconds() / ramp);
        double h = startHeight + (height - startHeight) * f;
        for (int leg = 0; leg < LEGS; leg++) {
            feet[3 * leg + 2] = -(h - FOOT_RADIUS);
        }
        c.outputAll(Value.ofDoubles(feet));
    }
}
