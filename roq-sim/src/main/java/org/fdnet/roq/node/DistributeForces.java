package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;
import static org.fdnet.roq.sim.RoqGeometry.TOTAL_MASS;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Distributes RoQ's weight over the feet on the ground ({@link ForceDistribution}) every {@value #STEP_MS} ms: reads
 * the {@code gait phase} ({@link GaitPhase}: which foot is in the air, which is being unloaded or loaded and how far),
 * the {@code joint angles}, {@code foot forces} and {@code attitude} (where the feet are and where the weight comes
 * down, {@link SensedFeet}), and writes the Data named {@code sole targets}: the sole force each foot should carry,
 * N (−1 for a foot in the air). Every foot on the ground is asked for at least {@code least} N (default 15) except
 * the one whose share the gait is moving.
 *
 * <p>It also counts, into the Data named {@code slack ticks} when connected, the firings at which a foot in stance —
 * on the ground and not the one being loaded or unloaded — bore less than {@code least} N by its sole sensor.
 */
public class DistributeForces extends Relation {
    static final int STEP_MS = 10;
    /** RoQ's weight, N. */
    static final double WEIGHT = TOTAL_MASS * 9.81;
    /** Time constant of the centre of pressure's running mean, s. */
    private static final double SMOOTHING = 0.05;

    public static final ParameterSpec<Double> LEAST = ParameterSpec.number("least").unit("N").range(0, WEIGHT / 4)
            .defaultValue(15.0).describe("the least load asked of every foot in stance").live();

    private final SensedFeet sensed = new SensedFeet();
    private final ForceDistribution distribution = new ForceDistribution();
    private final double[] x = new double[LEGS];
    private final double[] y = new double[LEGS];
    private final boolean[] down = new boolean[LEGS];
    private final double[] targets = new double[LEGS];
    private final double[] cop = new double[2];
    private double cx = Double.NaN;
    private double cy;
    private double least;
    private double last = Double.NaN;
    private long slack;

    @Override
    protected void init(NodeParameters p) {
        least = LEAST.read(p);
    }

    @Override
    protected void compute(RelationContext c) {
        double now = c.seconds();
        if (!Double.isNaN(last) && now - last < (STEP_MS - 0.5) / 1000.0) {
            return;
        }
        if (!sensed.read(SensedFeet.named(c, "joint angles"), SensedFeet.named(c, "foot forces"),
                SensedFeet.named(c, "attitude"))) {
            return;
        }
        double dt = Double.isNaN(last) ? 0 : now - last;
        last = now;
        GaitPhase phase = GaitPhase.of(SensedFeet.named(c, "gait phase"));
        if (sensed.centreOfPressure(WEIGHT / 2, cop)) {
            double a = Double.isNaN(cx) ? 1 : 1 - Math.exp(-dt / SMOOTHING);
            cx = Double.isNaN(cx) ? cop[0] : cx + (cop[0] - cx) * a;
            cy += (cop[1] - cy) * a;
        }
        if (Double.isNaN(cx)) {
            return;
        }
        int slackNow = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            x[leg] = sensed.position[3 * leg];
            y[leg] = sensed.position[3 * leg + 1];
            down[leg] = !(phase.inAir() && phase.leg() == leg);
            boolean inStance = down[leg] && phase.unloading() != leg && phase.leg() >= 0;
            if (inStance && sensed.force[leg] < least) {
                slackNow++;
            }
        }
        distribution.distribute(x, y, down, cx, cy, WEIGHT, least, phase.unloading(), phase.unloaded(), targets);
        c.output("sole targets", Value.ofDoubles(targets.clone()));
        if (slackNow > 0 && c.outputIndex("slack ticks") >= 0) {
            slack += slackNow;
            c.output("slack ticks", Value.of(slack));
        }
    }
}
