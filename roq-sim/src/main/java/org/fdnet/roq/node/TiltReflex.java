package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import java.util.Locale;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * The tilt reflex: when RoQ starts to tip, set the swinging foot down at once. Event-driven — give it no
 * {@code period}: it fires whenever the inclinometer or the gyro delivers (every snapshot), so its answer leaves in
 * the same pass through the network as the reading that called for it.
 *
 * <p>Inputs, in Reader order: (0) the inclinometer {roll, pitch} (rad, {@code attitude}); (1) the IMU gyro
 * {roll rate, pitch rate, yaw rate} (rad/s, {@code imu_gyro}; may be missing, then only the tilt counts); (2) the
 * gait's feet (12 numbers, body frame); (3) the gait phase {leg, 1 while in the air}. Output: a correction of the
 * feet (12 numbers) for {@link PostureIntegration}, so it reaches the servos through the same inverse kinematics and
 * {@link JointTargets} as the gait: zero, except while the reflex holds, when it lowers the swinging foot to the
 * height of the feet on the ground and {@code press} m (default 0.01) below it.
 *
 * <p>It triggers when |roll| or |pitch| exceeds {@code tilt} (rad, default 0.15) or the roll or pitch rate exceeds
 * {@code rate} (rad/s, default 1.0; the undisturbed crawl reaches 0.125 rad and 0.7 rad/s), and holds {@code hold} s (default 0.3) after the last reading that triggered
 * it. The correction is written only when it changes. Reports "caught leg L at t s" on each trigger.
 */
public class TiltReflex extends Relation {
    private static final int ATTITUDE = 0;
    private static final int GYRO = 1;
    private static final int FEET = 2;
    private static final int PHASE = 3;

    private double tilt;
    private double rate;
    private double hold;
    private double press;
    private double holdUntil = Double.NEGATIVE_INFINITY;
    private int caughtLeg = -1;
    private final double[] correction = new double[3 * LEGS];
    private boolean written;

    @Override
    protected void init(NodeParameters p) {
        tilt = p.doubleValue("tilt", 0.15);
        rate = p.doubleValue("rate", 1.0);
        hold = p.doubleValue("hold", 0.3);
        press = p.doubleValue("press", 0.01);
        if (!(tilt > 0 && tilt < 1)) {
            throw p.invalid("tilt", "must lie between 0 and 1 rad, was " + tilt);
        }
        if (!(rate > 0 && rate < 20)) {
            throw p.invalid("rate", "must lie between 0 and 20 rad/s, was " + rate);
        }
        if (!(hold >= 0 && hold <= 5)) {
            throw p.invalid("hold", "must lie between 0 and 5 s, was " + hold);
        }
        if (!(press >= 0 && press <= 0.05)) {
            throw p.invalid("press", "must lie between 0 and 0.05 m, was " + press);
        }
        if (p.has("period")) {
            throw p.invalid("period", "the tilt reflex fires on its inputs; a period would only delay it");
        }
    }

    @Override
    protected void compute(RelationContext c) {
        Value feet = c.inputCount() > FEET ? c.input(FEET) : null;
        Value phase = c.inputCount() > PHASE ? c.input(PHASE) : null;
        if (feet == null || feet.length() != 3 * LEGS || phase == null || phase.length() < 2) {
            c.report("needs attitude, gyro, gait feet and gait phase");
            return;
        }
        int swinging = phase.element(1) > 0.5 ? (int) phase.element(0) : -1;
        if (tipping(c.input(ATTITUDE), c.inputCount() > GYRO ? c.input(GYRO) : null)) {
            if (swinging >= 0 && caughtLeg != swinging) {
                c.report(String.format(Locale.ROOT, "caught leg %d at %.3f s", swinging, c.seconds()));
            }
            caughtLeg = swinging >= 0 ? swinging : caughtLeg;
            holdUntil = c.seconds() + hold;
        } else if (c.seconds() > holdUntil) {
            caughtLeg = -1;
        }
        boolean changed = lower(caughtLeg == swinging ? caughtLeg : -1, feet);
        if (changed || !written) {
            c.outputAll(Value.ofDoubles(correction));
            written = true;
        }
    }

    private boolean tipping(Value attitude, Value gyro) {
        boolean tilted = attitude != null && attitude.length() >= 2
                && (Math.abs(attitude.element(0)) > tilt || Math.abs(attitude.element(1)) > tilt);
        boolean turning = gyro != null && gyro.length() >= 2
                && (Math.abs(gyro.element(0)) > rate || Math.abs(gyro.element(1)) > rate);
        return tilted || turning;
    }

    /** Sets the correction: leg {@code leg}'s foot down to the stance feet's height and {@code press} below. */
    private boolean lower(int leg, Value feet) {
        double dz = 0;
        if (leg >= 0 && leg < LEGS) {
            double ground = 0;
            for (int other = 0; other < LEGS; other++) {
                ground += other == leg ? 0 : feet.element(3 * other + 2) / (LEGS - 1);
            }
            dz = Math.min(0, ground - feet.element(3 * leg + 2) - press);
        }
        boolean changed = false;
        for (int l = 0; l < LEGS; l++) {
            double want = l == leg ? dz : 0;
            changed |= correction[3 * l + 2] != want;
            correction[3 * l + 2] = want;
        }
        return changed;
    }
}
