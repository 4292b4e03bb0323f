package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * The stance legs track the sole forces {@link DistributeForces} asks for, by admittance on top of the position
 * servos: reads {@code sole targets} (N, −1 for a foot in the air), {@code foot forces}, {@code joint angles} and
 * {@code attitude}, and writes the Data named {@code sole admittance}: a height offset for each foot (12 numbers,
 * only z non-zero) that {@link PostureIntegration} adds to the feet.
 *
 * <p>With four feet down the weight's statics leave one mode free, the twist along which the diagonal pairs trade
 * load ({@link ForceDistribution}); only that mode is controlled: the force error along the twist, e, moves the feet
 * along it, Δz = {@code compliance}·e·twist·dt (a foot that bears too much rises, its diagonal partner too, the
 * other pair goes down), at most {@code reach} m (default 0.04). With three feet down the forces follow from where
 * the weight is and nothing is moved. The offset of a foot in the air fades out with a 0.15 s time constant.
 */
public class TrackSoleForces extends Relation {
    /** How fast the offset of a foot in the air fades, s. */
    private static final double FADE = 0.15;

    public static final ParameterSpec<Double> COMPLIANCE = ParameterSpec.number("compliance").unit("m/(N·s)")
            .range(0, 0.05).defaultValue(0.003).describe("how fast a foot moves per newton of force error").live();
    public static final ParameterSpec<Double> REACH = ParameterSpec.number("reach").unit("m").range(0, 0.1)
            .defaultValue(0.04).describe("the farthest a foot is moved up or down").live();

    private final SensedFeet sensed = new SensedFeet();
    private final double[] x = new double[LEGS];
    private final double[] y = new double[LEGS];
    private final double[] twist = new double[LEGS];
    private final double[] offset = new double[LEGS];
    private final double[] out = new double[3 * LEGS];
    private double compliance;
    private double reach;
    private double last = Double.NaN;

    @Override
    protected void init(NodeParameters p) {
        compliance = COMPLIANCE.read(p);
        reach = REACH.read(p);
    }

    @Override
    protected void compute(RelationContext c) {
        double now = c.seconds();
        if (!Double.isNaN(last) && now - last < (DistributeForces.STEP_MS - 0.5) / 1000.0) {
            return;
        }
        Value targets = SensedFeet.named(c, "sole targets");
        if (targets == null || targets.length() < LEGS || !sensed.read(SensedFeet.named(c, "joint angles"),
                SensedFeet.named(c, "foot forces"), SensedFeet.named(c, "attitude"))) {
            return;
        }
        double dt = Double.isNaN(last) ? 0 : Math.min(0.05, now - last);
        last = now;
        boolean four = true;
        for (int leg = 0; leg < LEGS; leg++) {
            x[leg] = sensed.position[3 * leg];
            y[leg] = sensed.position[3 * leg + 1];
            four &= targets.element(leg) >= 0;
        }
        if (four && ForceDistribution.twistMode(x, y, twist)) {
            double e = 0;
            for (int leg = 0; leg < LEGS; leg++) {
                e += twist[leg] * (sensed.force[leg] - targets.element(leg));
            }
            for (int leg = 0; leg < LEGS; leg++) {
                offset[leg] = Math.max(-reach, Math.min(reach, offset[leg] + compliance * e * twist[leg] * dt));
            }
        } else {
            double fade = 1 - Math.exp(-dt / FADE);
            for (int leg = 0; leg < LEGS; leg++) {
                if (targets.element(leg) < 0) {
                    offset[leg] -= offset[leg] * fade;
                }
            }
        }
        for (int leg = 0; leg < LEGS; leg++) {
            out[3 * leg + 2] = offset[leg];
        }
        c.outputAll(Value.ofDoubles(out.clone()));
    }
}
