package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import java.util.Locale;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Heading and track hold: estimates where RoQ faces and how far it has strayed from its course line (the straight
 * line ahead of where it started) from what it senses, and steers the crawl back onto that line.
 *
 * <p>The heading comes from the IMU's gyro (a Data named {@code imu gyro}, body-frame rates, rad/s), turned into the
 * heading's rate by the inclinometer's {@code attitude}. Its bias is measured or learnt one of two ways. With
 * {@code calibrate} (s, default 0: off) it is the gyro's mean rate while RoQ stands still for that long at the start
 * (the second half of it; the gait's {@code settle} must be as long), the way {@code roq-rubble.fdn} runs: the feet's
 * turn slips too much to teach it over a long crawl (measured in roq-networks.md). With {@code biasTime} (s, default
 * 20; 0: off) it is learnt slowly from leg odometry: the feet
 * that bear load (sole force over {@code contact} N, default 20, and not the leg the {@code gait phase} has in the
 * air) stay where they are on the ground, so the way their positions (forward kinematics of the measured joint
 * angles, levelled by the attitude, {@link SensedFeet}) turned in the body frame between two firings is the body's
 * own turn, reversed. Without a gyro that turn is the heading's. The position along and across the line is dead
 * reckoning along the heading at the crawl's {@code speed} (m/s, default 0.03): the feet slip too much under the
 * body's sway for their own odometry to tell how far it went (measured: it saw a fraction of the way).
 *
 * <p>The steering: the heading wished for is −{@code track} × lateral error (rad per m, default 1.5), at most
 * {@code maxHeading} rad (default 0.35) off the line; the turn is {@code gain} × (wished − estimated heading)
 * (default 0.8), at most {@code maxTurn} rad per stance (default 0.25). Outputs (by name, when connected):
 * {@code steer} the turn, rad per stance ({@link CrawlGait} reads it); {@code heading} the estimated heading, rad;
 * {@code track} the estimate {x, y, heading} from the start, m, m, rad.
 */
public class HoldCourse extends Relation {
    private final SensedFeet now = new SensedFeet();
    private final double[] before = new double[3 * LEGS];
    private final boolean[] loaded = new boolean[LEGS];
    private boolean haveBefore;
    private double contact;
    private double speed;
    private double trackGain;
    private double gain;
    private double maxHeading;
    private double maxTurn;
    private double x;
    private double y;
    private double heading;
    private double lastSeconds = Double.NaN;
    /** The gyro's yaw-rate bias learnt so far, rad/s. */
    private double gyroBias;
    /** How long the gyro's bias takes to learn from the feet, s (0: not learnt from them). */
    private double biasTime;
    /** How long RoQ stands at the start (the gait's {@code settle}), s: the gyro's bias is its mean rate then. */
    private double calibrate;
    private double firstSeconds = Double.NaN;
    /** While RoQ stands still: the gyro's turn and the time, summed. */
    private double standingGyro;
    private double standingTime;
    /** The newest gyro snapshot's tick integrated, its heading rate, and the turn and time integrated since the last
     * firing that acted. */
    private long gyroTick;
    private double lastRate = Double.NaN;
    private double gyroSum;
    private double gyroTime;
    /** How long the heading took the gyro's uncorrected rate while RoQ stood, s. */
    private double settled;

    public static final ParameterSpec<Double> CONTACT = ParameterSpec.number("contact").unit("N").above(0).defaultValue(20.0)
            .describe("the sole force above which a foot bears load (its odometry counts)");
    public static final ParameterSpec<Double> SPEED = ParameterSpec.number("speed").unit("m/s").range(0, 0.5)
            .defaultValue(0.03).describe("the crawl's speed, for dead reckoning along the heading");
    public static final ParameterSpec<Double> TRACK = ParameterSpec.number("track").unit("rad/m").atLeast(0)
            .defaultValue(1.5).describe("the heading wished for per metre of lateral error");
    public static final ParameterSpec<Double> GAIN = ParameterSpec.number("gain").atLeast(0).defaultValue(0.8)
            .describe("the turn per radian of heading error");
    public static final ParameterSpec<Double> MAX_HEADING = ParameterSpec.number("maxHeading").unit("rad").above(0)
            .atMost(1.5).defaultValue(0.35).describe("the most the wished heading leaves the line");
    public static final ParameterSpec<Double> MAX_TURN = ParameterSpec.number("maxTurn").unit("rad per stance").above(0)
            .atMost(0.3).defaultValue(0.25).describe("the largest turn asked of the gait");
    public static final ParameterSpec<Double> BIAS_TIME = ParameterSpec.number("biasTime").unit("s").range(1, 1000)
            .or(0.0).defaultValue(20.0).describe("the time constant the gyro's bias is learnt with from odometry (0: off)");
    public static final ParameterSpec<Double> CALIBRATE = ParameterSpec.number("calibrate").unit("s").range(0, 30)
            .defaultValue(0.0).describe("measure the gyro's bias while RoQ stands this long at the start (0: off)");

    @Override
    protected void init(NodeParameters p) {
        contact = CONTACT.read(p);
        speed = SPEED.read(p);
        trackGain = TRACK.read(p);
        gain = GAIN.read(p);
        maxHeading = MAX_HEADING.read(p);
        maxTurn = MAX_TURN.read(p);
        biasTime = BIAS_TIME.read(p);
        calibrate = CALIBRATE.read(p);
    }

    @Override
    protected void compute(RelationContext c) {
        if (!now.read(SensedFeet.named(c, "joint angles"), SensedFeet.named(c, "foot forces"),
                SensedFeet.named(c, "attitude"))) {
            return;
        }
        double seconds = c.seconds();
        if (Double.isNaN(firstSeconds)) {
            firstSeconds = seconds;
        }
        boolean calibrating = seconds - firstSeconds < calibrate;
        integrateGyro(c);
        if (!Double.isNaN(lastSeconds) && seconds - lastSeconds < KeepBalance.STEP) {
            return; // the joint angles change every tick: act on them every 10 ms
        }
        double dt = Double.isNaN(lastSeconds) ? 0 : seconds - lastSeconds;
        lastSeconds = seconds;
        if (gyroTime == 0 && !Double.isNaN(lastRate)) {
            // values without a snapshot's tick: sample the rate once per firing
            gyroSum = lastRate * dt;
            gyroTime = dt;
        }
        double rawTurn = gyroTime > 0 ? gyroSum : Double.NaN;
        double rawTime = gyroTime;
        gyroSum = 0;
        gyroTime = 0;
        if (calibrating) {
            standStill(seconds - firstSeconds >= calibrate / 2, rawTurn, rawTime, swinging(c));
            put(c, "steer", Value.ofDoubles(0));
            return;
        }
        if (standingTime > 0) {
            gyroBias = standingGyro / standingTime;
            heading -= gyroBias * settled;
            standingTime = 0;
        }
        double gyroTurn = Double.isNaN(rawTurn) ? Double.NaN : rawTurn - gyroBias * rawTime;
        if (haveBefore) {
            odometry(swinging(c), gyroTurn, dt);
            // dead reckoning along the heading at the crawl's speed: the feet slip too much under the body's sway
            // for their own odometry to tell how far it went (measured: it saw a fraction of the way)
            x += speed * dt * Math.cos(heading);
            y += speed * dt * Math.sin(heading);
        }
        keepFeet(swinging(c));
        double wished = clamp(-trackGain * y, maxHeading);
        double turn = clamp(gain * (wished - heading), maxTurn);
        put(c, "steer", Value.ofDoubles(turn));
        put(c, "heading", Value.of(heading));
        put(c, "track", Value.ofDoubles(x, y, heading));
        c.report(String.format(Locale.ROOT, "track %.3f m, heading %.3f rad, turn %.3f", y, heading, turn));
    }

    /**
     * The heading's turn since the last firing: the gyro's ({@code gyroTurn}, NaN without one), its bias learnt
     * from the feet's turn; the feet's alone without a gyro.
     */
    private void odometry(int swinging, double gyroTurn, double dt) {
        double feetTurn = feetTurn(swinging);
        if (Double.isNaN(feetTurn)) {
            if (!Double.isNaN(gyroTurn)) {
                heading += gyroTurn;
            }
            return;
        }
        double turn = feetTurn;
        if (!Double.isNaN(gyroTurn)) {
            // the gyro turns with the body whatever the feet do (they slip); its bias is learnt slowly from the
            // feet's turn, which has no bias but slips
            if (biasTime > 0) {
                gyroBias += (gyroTurn - feetTurn) / biasTime;
            }
            turn = gyroTurn;
        }
        heading += turn;
    }

    /**
     * The body's turn since the last firing by the feet loaded then and now (at least two): the best rotation of
     * their body-frame positions (2-D Procrustes), reversed; NaN with fewer than two.
     */
    private double feetTurn(int swinging) {
        double bx = 0;
        double by = 0;
        double nx = 0;
        double ny = 0;
        int n = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            if (loaded[leg] && now.force[leg] > contact && leg != swinging) {
                bx += before[3 * leg];
                by += before[3 * leg + 1];
                nx += now.position[3 * leg];
                ny += now.position[3 * leg + 1];
                n++;
            }
        }
        if (n < 2) {
            return Double.NaN;
        }
        bx /= n;
        by /= n;
        nx /= n;
        ny /= n;
        double cross = 0;
        double dot = 0;
        for (int leg = 0; leg < LEGS; leg++) {
            if (loaded[leg] && now.force[leg] > contact && leg != swinging) {
                double ax = before[3 * leg] - bx;
                double ay = before[3 * leg + 1] - by;
                double qx = now.position[3 * leg] - nx;
                double qy = now.position[3 * leg + 1] - ny;
                cross += ax * qy - ay * qx;
                dot += ax * qx + ay * qy;
            }
        }
        return -Math.atan2(cross, dot);
    }

    /**
     * Integrates the gyro's heading rate over every snapshot the network was given (each held until the next, by the
     * snapshots' ticks), not once per firing: the body's yaw rate shakes at many hertz, and sampling it every 10 ms
     * adds a random walk to the heading.
     */
    private void integrateGyro(RelationContext c) {
        Value gyro = SensedFeet.named(c, "imu gyro");
        double rate = headingRate(c);
        if (Double.isNaN(rate)) {
            return;
        }
        long tick = gyro.tick();
        if (tick <= 0) {
            lastRate = rate; // no snapshot's tick: compute() samples it per firing
            return;
        }
        if (tick <= gyroTick) {
            return;
        }
        if (gyroTick > 0) {
            double step = (tick - gyroTick) * RoqGeometry.TIMESTEP;
            gyroSum += lastRate * step;
            gyroTime += step;
        }
        gyroTick = tick;
        lastRate = rate;
    }

    /**
     * While RoQ stands (the gait's {@code settle}): the heading takes the gyro's whole turn. In the second half
     * ({@code still}), when the body has settled, the gyro's mean rate is its bias; it is taken off the turn over the
     * whole settling when walking starts. (The body still creeps about 2 mrad/s then, as the balance holds it over
     * three feet, and that goes into the bias; taking the feet's turn off it made it worse, measured.)
     */
    private void standStill(boolean still, double rawTurn, double rawTime, int swinging) {
        if (!Double.isNaN(rawTurn)) {
            heading += rawTurn;
            settled += rawTime;
            if (still) {
                standingGyro += rawTurn;
                standingTime += rawTime;
            }
        }
        keepFeet(swinging);
    }

    /** Keeps the feet's positions and which bear load, for the next firing's odometry. */
    private void keepFeet(int swinging) {
        System.arraycopy(now.position, 0, before, 0, before.length);
        for (int leg = 0; leg < LEGS; leg++) {
            loaded[leg] = now.force[leg] > contact && leg != swinging;
        }
        haveBefore = true;
    }

    /** The heading's rate from the gyro's body-frame rates turned by the attitude, rad/s, or NaN without them. */
    private static double headingRate(RelationContext c) {
        Value gyro = SensedFeet.named(c, "imu gyro");
        Value attitude = SensedFeet.named(c, "attitude");
        if (gyro == null || gyro.length() < 3 || attitude == null || attitude.length() < 2) {
            return Double.NaN;
        }
        // (sin roll * q + cos roll * r) / cos pitch
        double roll = attitude.element(0);
        return (Math.sin(roll) * gyro.element(1) + Math.cos(roll) * gyro.element(2)) / Math.cos(attitude.element(1));
    }

    /** The leg the gait's phase (the Data named {@code gait phase}) has in the air or probing, else -1. */
    private static int swinging(RelationContext c) {
        Value phase = SensedFeet.named(c, "gait phase");
        boolean up = phase != null && phase.length() > 1
                && (phase.element(1) > 0.5 || phase.length() > 2 && phase.element(2) > 0.5);
        return up ? (int) phase.element(0) : -1;
    }

    private static void put(RelationContext c, String name, Value v) {
        int i = c.outputIndex(name);
        if (i >= 0) {
            c.output(i, v);
        }
    }

    private static double clamp(double v, double limit) {
        return Math.max(-limit, Math.min(limit, v));
    }
}
