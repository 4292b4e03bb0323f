package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
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
 * {@link JointTargets} as the gait: zero while RoQ does not tip. Inputs named {@code balance shift} (the shift
 * {@link KeepBalance} adds to every foot) and {@code foot forces} (the soles, N) are optional: see {@code unlean}.
 *
 * <p>It triggers when |roll| or |pitch| exceeds {@code tilt} (rad, default 0.15) or the roll or pitch rate exceeds
 * {@code rate} (rad/s, default 1.0; the undisturbed crawl reaches 0.125 rad and 0.7 rad/s), and holds {@code hold} s
 * (default 0.3) after the last reading that triggered it. While it holds:
 * <ul>
 *   <li>the swinging foot goes down to the height of the feet on the ground and {@code press} m (default 0.01)
 *   below it, and up to {@code step} m (default 0) along the way RoQ falls: a catching step, where the body goes,
 *   scaled by how far that foot lies on the side RoQ falls to (the cosine between the foot's direction from the
 *   body's centre and the fall; none for a foot on the other side, which would only narrow the stance);</li>
 *   <li>the feet on the ground move {@code shift} m (default 0) along the way RoQ falls, that is the body moves that
 *   far against the fall, away from the edge it tips over;</li>
 *   <li>every foot rises {@code crouch} m (default 0, at most {@link #MOST_CROUCH}): the body sinks, which shortens
 *   the lever a push at the body has about the feet — and, once a strong push slides RoQ, the lever the feet's
 *   friction has about the centre of mass, which is what turns a slide into a fall. The caught foot crouches only
 *   once it is down, so it is not lifted while it is being set down;</li>
 *   <li>once the caught foot is down (its sole, input {@code foot forces}, carries more than 20 N; at once when no
 *   foot was in the air or the soles are not read), the share {@code unlean} (0..1, default 0) of Balance's lean is
 *   taken back: with four feet down the whole rectangle is the support, and the lean towards the three-foot
 *   triangle's centroid (up to 15 cm) only brings the body nearer the edges on its side, so that sideways and
 *   backwards a network that kept the lean survives smaller pushes than RoQ without Balance. Before the foot is down the lean is
 *   what keeps the body over the triangle. It reads Balance's latest shift on every firing, so Balance, still
 *   integrating, cannot pull the body back while the brace holds.</li>
 * </ul>
 * The way RoQ falls is the direction the top of the body moves, seen from above: (pitch rate, −roll rate) from the
 * gyro while a rate triggers, else (pitch, −roll) from the inclinometer (pitch > 0: nose down; roll > 0: left side
 * up), read when the brace begins and kept while it holds. Sensed values only. After the hold, the shift and crouch fade out over {@code release} s (default 0: at once)
 * so the body does not lurch back. The correction is written only when it changes; "caught leg L at t s" is
 * reported on each trigger. The report is built before the firing's outputs are committed (the engine commits them
 * when {@code compute} returns), so it is appended to a kept builder: a string concatenation's first run links its
 * call site, which costs milliseconds on the reflex's first catch ({@code bench roq --part b --trace} shows it).
 */
public class TiltReflex extends Relation {
    private static final int ATTITUDE = 0;
    private static final int GYRO = 1;
    private static final int FEET = 2;
    private static final int PHASE = 3;
    /** A sole carrying more than this is down, N (RoQ's stance feet carry 50–90 N each when it walks). */
    private static final double LOADED = 20;
    /**
     * The deepest crouch, m: the gait carries the body's centre 0.27 m up, so its underside (5 cm below) stays 7 cm
     * above level ground even at this depth.
     */
    static final double MOST_CROUCH = 0.15;

    private double tilt;
    private double rate;
    private double hold;
    private double press;
    private double step;
    private double shift;
    private double crouch;
    private double release;
    private double unlean;
    private double holdUntil = Double.NEGATIVE_INFINITY;
    private double fallX;
    private double fallY;
    private int caughtLeg = -1;
    /** Whether all four feet have been down since this brace began: then Balance's lean is given back. */
    private boolean fourDown;
    private final double[] correction = new double[3 * LEGS];
    private boolean written;
    private final StringBuilder report = new StringBuilder(32);

    /** Event-driven: a period would only delay the reflex. */
    public static final ParameterSpec<Long> PERIOD = Relation.PERIOD.range(0, 0)
            .describe("none: the tilt reflex fires on its inputs; a period would only delay it");
    public static final ParameterSpec<Double> TILT = ParameterSpec.number("tilt").unit("rad").above(0).below(1)
            .defaultValue(0.15).describe("the roll or pitch that triggers it").live();
    public static final ParameterSpec<Double> RATE = ParameterSpec.number("rate").unit("rad/s").above(0).below(20)
            .defaultValue(1.0).describe("the roll or pitch rate that triggers it").live();
    public static final ParameterSpec<Double> HOLD = ParameterSpec.number("hold").unit("s").range(0, 5).defaultValue(0.3)
            .describe("how long it holds after the last reading that triggered it").live();
    public static final ParameterSpec<Double> PRESS = ParameterSpec.number("press").unit("m").range(0, 0.05)
            .defaultValue(0.01).describe("how far below the feet on the ground the swinging foot goes down").live();
    public static final ParameterSpec<Double> STEP = ParameterSpec.number("step").unit("m").range(0, 0.2).defaultValue(0.0)
            .describe("the catching step of the swinging foot along the way RoQ falls").live();
    public static final ParameterSpec<Double> SHIFT = ParameterSpec.number("shift").unit("m").range(0, 0.15)
            .defaultValue(0.0).describe("how far the feet on the ground move along the way RoQ falls").live();
    public static final ParameterSpec<Double> CROUCH = ParameterSpec.number("crouch").unit("m").range(0, MOST_CROUCH)
            .defaultValue(0.0).describe("how far every foot rises, so the body sinks").live();
    public static final ParameterSpec<Double> RELEASE = ParameterSpec.number("release").unit("s").range(0, 5)
            .defaultValue(0.0).describe("the time the shift and crouch fade out over after the hold").live();
    public static final ParameterSpec<Double> UNLEAN = ParameterSpec.number("unlean").range(0, 1).defaultValue(0.0)
            .describe("the share of Balance's lean taken back once the caught foot is down").live();

    @Override
    protected void init(NodeParameters p) {
        tilt = TILT.read(p);
        rate = RATE.read(p);
        hold = HOLD.read(p);
        press = PRESS.read(p);
        step = STEP.read(p);
        shift = SHIFT.read(p);
        crouch = CROUCH.read(p);
        release = RELEASE.read(p);
        unlean = UNLEAN.read(p);
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
        int leg = caughtLeg == swinging ? caughtLeg : -1;
        fourDown = brace > 0 && (fourDown || down(leg, SensedFeet.named(c, "foot forces")));
        if (brace(leg, feet, fourDown ? SensedFeet.named(c, "balance shift") : null, brace) || !written) {
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

    /**
     * Whether the caught foot ({@code leg}, −1: none in the air) is down: its sole carries more than {@link #LOADED}
     * N. Without sole forces ({@code soles} missing) it counts as down at once.
     */
    private static boolean down(int leg, Value soles) {
        return leg < 0 || soles == null || soles.length() < LEGS || soles.element(leg) > LOADED;
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
     * up to {@code step} along the fall; every other foot {@code shift} along the fall; all up {@code crouch}; every
     * foot back by {@code unlean} of Balance's shift {@code lean} (null: none); all but the lowering scaled by
     * {@code brace} (1 while the reflex holds, fading to 0 after). True when it changed.
     */
    private boolean brace(int leg, Value feet, Value lean, double brace) {
        double dz = 0;
        if (leg >= 0 && leg < LEGS) {
            double ground = 0;
            for (int other = 0; other < LEGS; other++) {
                ground += other == leg ? 0 : feet.element(3 * other + 2) / (LEGS - 1);
            }
            dz = Math.min(0, ground - feet.element(3 * leg + 2) - press);
        }
        // four feet down make the whole rectangle the support: Balance's lean over the three-foot triangle only
        // brings the body nearer the edges on its side, so give it back (the balance shift's negative, 12 numbers)
        double backX = 0;
        double backY = 0;
        if (lean != null && lean.length() == 3 * LEGS) {
            backX = -lean.element(0) * unlean * brace;
            backY = -lean.element(1) * unlean * brace;
        }
        // a catching step only catches on the side RoQ falls to: none for a foot on the other side
        double stepped = 0;
        if (leg >= 0 && leg < LEGS) {
            double fx = feet.element(3 * leg);
            double fy = feet.element(3 * leg + 1);
            double n = Math.hypot(fx, fy);
            stepped = n > 0 ? step * Math.max(0, (fx * fallX + fy * fallY) / n) : 0;
        }
        boolean changed = false;
        for (int l = 0; l < LEGS; l++) {
            double along = brace * (l == leg ? stepped : shift);
            changed |= set(3 * l, along * fallX + backX);
            changed |= set(3 * l + 1, along * fallY + backY);
            // the caught foot crouches with the others only once it is down: crouching it on its way would lift it
            // as fast as it is lowered (with a 14 cm crouch it landed 40 ms later than with no reflex at all)
            changed |= set(3 * l + 2, l == leg ? dz + (fourDown ? brace * crouch : 0) : brace * crouch);
        }
        return changed;
    }

    private boolean set(int i, double v) {
        boolean changed = correction[i] != v;
        correction[i] = v;
        return changed;
    }
}
