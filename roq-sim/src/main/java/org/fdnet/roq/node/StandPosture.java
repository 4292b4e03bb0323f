package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.*;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
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

    public static final ParameterSpec<Double> HEIGHT = ParameterSpec.number("height").unit("m").range(0.10, 0.55)
            .defaultDescribed("the standing pose's height").describe("the body's height above the ground").live();
    public static final ParameterSpec<Double> RAMP = ParameterSpec.number("ramp").unit("s").atLeast(0).defaultValue(1.0)
            .describe("the time it takes from the standing pose's height to height").live();

    @Override
    protected void init(NodeParameters p) {
        startHeight = standingHeight();
        height = HEIGHT.readOr(p, startHeight);
        ramp = RAMP.read(p);
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
