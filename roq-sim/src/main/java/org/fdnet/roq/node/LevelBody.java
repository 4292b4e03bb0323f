package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Slope posture: levels the body by attitude feedback. On an incline the crawl's feet, all at one height in the
 * body frame, tilt the body with the ground, and the centre of mass hangs downhill of the feet (0.07 m on 15°). This
 * Relation turns the feet's plane against the tilt the inclinometer measures: each foot's height in the body frame
 * moves by −x·tan(pitch levelled) + y·tan(roll levelled), so the uphill legs shorten and the downhill legs lengthen
 * and the body pitches and rolls back toward level.
 *
 * <p>The angles levelled are integrators on the measured {@code attitude} (roll, pitch; roll &gt; 0 the left side
 * up, pitch &gt; 0 the nose down): each grows by the measured tilt over {@code tau} s (default 1.5 — slower than the
 * crawl's sway, so it follows the ground's slope and not the body's rocking), at most {@code maxAngle} rad (default
 * 0.3), and no foot moves more than {@code reach} m (default 0.09: what the legs have to spare around the crawl's
 * 0.27 m body height). Inputs (by name): {@code attitude} (required) and the feet the gait commands ({@code gait
 * feet}, 12, body frame: the x and y each foot's correction is taken at). Output (0): the correction to add to the
 * feet (12; only z is non-zero); also the two angles levelled {roll, pitch} to an output named {@code level
 * angles} when one is connected. Reads sensed values only (the inclinometer), never ground truth.
 */
public class LevelBody extends Relation {
    private final double[] correction = new double[3 * LEGS];
    private double tau;
    private double maxAngle;
    private double reach;
    private double roll;
    private double pitch;
    private double lastSeconds = Double.NaN;

    public static final ParameterSpec<Double> TAU = ParameterSpec.number("tau").unit("s").range(0.1, 30).defaultValue(1.5)
            .describe("the time constant of the levelling integrators").live();
    public static final ParameterSpec<Double> MAX_ANGLE = ParameterSpec.number("maxAngle").unit("rad").range(0, 0.6)
            .defaultValue(0.3).describe("the largest angle levelled").live();
    public static final ParameterSpec<Double> REACH = ParameterSpec.number("reach").unit("m").range(0, 0.15)
            .defaultValue(0.09).describe("the most any foot moves").live();

    @Override
    protected void init(NodeParameters p) {
        tau = TAU.read(p);
        maxAngle = MAX_ANGLE.read(p);
        reach = REACH.read(p);
    }

    @Override
    protected void compute(RelationContext c) {
        Value attitude = c.input("attitude");
        Value feet = c.inputIndex("gait feet") >= 0 ? c.input("gait feet") : null;
        double now = c.seconds();
        double dt = Double.isNaN(lastSeconds) ? 0 : Math.min(0.05, Math.max(0, now - lastSeconds));
        lastSeconds = now;
        if (attitude == null || attitude.length() < 2 || feet == null || feet.length() < 3 * LEGS) {
            c.report("waiting for the attitude and the gait's feet");
            return;
        }
        // the body's tilt is what is left after the levelling so far: integrate it until the body is level
        roll = clamp(roll + attitude.element(0) * dt / tau, maxAngle);
        pitch = clamp(pitch + attitude.element(1) * dt / tau, maxAngle);
        double tanRoll = Math.tan(roll);
        double tanPitch = Math.tan(pitch);
        for (int leg = 0; leg < LEGS; leg++) {
            double x = feet.element(3 * leg);
            double y = feet.element(3 * leg + 1);
            // pitch > 0 (nose down): the front feet go down in the body frame, the nose comes up; roll > 0 (left up):
            // the left feet go up, the left side comes down
            correction[3 * leg + 2] = clamp(-x * tanPitch + y * tanRoll, reach);
        }
        c.output(0, Value.ofDoubles(correction));
        int angles = c.outputIndex("level angles");
        if (angles >= 0) {
            c.output(angles, Value.ofDoubles(roll, pitch));
        }
    }

    private static double clamp(double v, double limit) {
        return Math.max(-limit, Math.min(limit, v));
    }
}
