package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * The tilt reflex: when RoQ starts to tip, set the swinging foot down at once and brace against the fall.
 * Event-driven — give it no {@code period}: it fires whenever the inclinometer or the gyro delivers (every snapshot),
 * so its answer leaves in the same pass through the network as the reading that called for it.
 *
 * <p>Inputs, in Reader order: (0) the inclinometer {roll, pitch} (rad, {@code attitude}); (1) the IMU gyro
 * {roll rate, pitch rate, yaw rate} (rad/s, {@code imu_gyro}; may be missing, then only the tilt counts); (2) the
 * gait's feet (12 numbers, body frame); (3) the gait phase {leg, 1 while in the air}. Output: a correction of the
 * feet (12 numbers) for {@link PostureIntegration}, so it reaches the servos through the same inverse kinematics and
 * {@link JointTargets} as the gait: zero while RoQ does not tip.
 *
 * <p>It triggers when |roll| or |pitch| exceeds {@code tilt} (rad, default 0.15) or the roll or pitch rate exceeds
 * {@code rate} (rad/s, default 1.0; the undisturbed crawl reaches 0.125 rad and 0.7 rad/s), and holds {@code hold} s
 * (default 0.3) after the last reading that triggered it. While it holds:
 * <ul>
 *   <li>the swinging foot goes down to the height of the feet on the ground and {@code press} m (default 0.01)
 *   below it, and {@code step} m (default 0) along the way RoQ falls: a catching step, where the body goes;</li>
 *   <li>the feet on the ground move {@code shift} m (default 0) along the way RoQ falls, that is the body moves that
 *   far against the fall, away from the edge it tips over;</li>
 *   <li>every foot rises {@code crouch} m (default 0): the body sinks, which shortens the lever a push at the body
 *   has about the feet.</li>
 * </ul>
 * The way RoQ falls is the direction the top of the body moves, seen from above: (pitch rate, −roll rate) from the
 * gyro while a rate triggers, else (pitch, −roll) from the inclinometer (pitch > 0: nose down; roll > 0: left side
 * up), read when the brace begins and kept while it holds. Sensed values only. After the hold, the shift and crouch fade out over {@code release} s (default 0: at once)
 * so the body does not lurch back. The correction is written only when it changes; "caught leg L at t s" is
 * reported on each trigger. The report is built before the firing's outputs are committed (the engine commits them
 * when {@code compute} returns), so it is appended to a kept builder: a string concatenation's first run links its
 * call site, and that cost 2.6–3.4 ms on the reflex's first catch (bench roq (b) --trace, session 6).
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
    private double step;
    private double shift;
    private double crouch;
    private double release;
    private double holdUntil = Double.NEGATIVE_INFINITY;
    private double fallX;
    private double fallY;
    private int caughtLeg = -1;
    private final double[] correction = new double[3 * LEGS];
    private boolean written;
    private final StringBuilder report = new StringBuilder(32);

    @Override
    protected void init(NodeParameters p) {
        tilt = p.doubleValue("tilt", 0.15);
        rate = p.doubleValue("rate", 1.0);
        hold = p.doubleValue("hold", 0.3);
        press = p.doubleValue("press", 0.01);
        step = p.doubleValue("step", 0);
        shift = p.doubleValue("shift", 0);
        crouch = p.doubleValue("crouch", 0);
        release = p.doubleValue("release", 0);
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
        if (!(step >= 0 && step <= 0.2)) {
            throw p.invalid("step", "must lie between 0 and 0.2 m, was " + step);
        }
        if (!(shift >= 0 && shift <= 0.15)) {
            throw p.invalid("shift", "must lie between 0 and 0.15 m, was " + shift);
        }
        if (!(crouch >= 0 && crouch <= 0.1)) {
            throw p.invalid("crouch", "must lie between 0 and 0.1 m, was " + crouch);
        }
        if (!(release >= 0 && release <= 5)) {
            throw p.invalid("release", "must lie between 0 and 5 s, was " + release);
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
        double now = c.seconds();
        int swinging = phase.element(1) > 0.5 ? (int) phase.element(0) : -1;
        boolean caughtNow = false;
        boolean bracing = now <= holdUntil;
        if (tipping(c.input(ATTITUDE), c.inputCount() > GYRO ? c.input(GYRO) : null, !bracing)) {
            caughtNow = swinging >= 0 && caughtLeg != swinging;
            caughtLeg = swinging >= 0 ? swinging : caughtLeg;
            holdUntil = now + hold;
        } else if (now > holdUntil) {
            caughtLeg = -1;
        }
        double brace = now <= holdUntil ? 1 : release > 0 ? Math.max(0, 1 - (now - holdUntil) / release) : 0;
        if (brace(caughtLeg == swinging ? caughtLeg : -1, feet, brace) || !written) {
            c.outputAll(Value.ofDoubles(correction));
            written = true;
        }
        if (caughtNow) {
            report.setLength(0);
            c.report(report.append("caught leg ").append(swinging).append(" at ").append(Math.round(now * 1000) / 1000.0)
                    .append(" s").toString());
        }
    }

    /**
     * Whether RoQ tips; when it does and {@code aim}, the way it falls goes to {@link #fallX}, {@link #fallY}. The way
     * is taken once, when a brace begins: the brace's own move turns the body, and a way read again from that turn
     * flips the brace back and forth (measured: the stance feet swung ±8 cm every 0.1 s for 2 s).
     */
    private boolean tipping(Value attitude, Value gyro, boolean aim) {
        boolean tilted = attitude != null && attitude.length() >= 2
                && (Math.abs(attitude.element(0)) > tilt || Math.abs(attitude.element(1)) > tilt);
        boolean turning = gyro != null && gyro.length() >= 2
                && (Math.abs(gyro.element(0)) > rate || Math.abs(gyro.element(1)) > rate);
        if (!aim) {
            return tilted || turning;
        }
        if (turning) {
            fallTowards(gyro.element(1), -gyro.element(0));
        } else if (tilted) {
            fallTowards(attitude.element(1), -attitude.element(0));
        }
        return tilted || turning;
    }

    private void fallTowards(double x, double y) {
        double n = Math.hypot(x, y);
        if (n > 0) {
            fallX = x / n;
            fallY = y / n;
        }
    }

    /**
     * Sets the correction: leg {@code leg} (−1: none) down to the stance feet's height, {@code press} below and
     * {@code step} along the fall; every other foot {@code shift} along the fall; all up {@code crouch}; the shift,
     * step and crouch scaled by {@code brace} (1 while the reflex holds, fading to 0 after). True when it changed.
     */
    private boolean brace(int leg, Value feet, double brace) {
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
            double along = brace * (l == leg ? step : shift);
            changed |= set(3 * l, along * fallX);
            changed |= set(3 * l + 1, along * fallY);
            changed |= set(3 * l + 2, (l == leg ? dz : 0) + brace * crouch);
        }
        return changed;
    }

    private boolean set(int i, double v) {
        boolean changed = correction[i] != v;
        correction[i] = v;
        return changed;
    }
}
