package org.fdnet.roq.node;

import static org.fdnet.roq.sim.RoqGeometry.LEGS;

import java.util.Locale;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * Probe the ground — the thesis's "active movement sense": before the gait puts weight on a new foothold, the
 * swung foot is lowered until its sole reads {@code testForce} N (default 55: above a fragile cell's 40 N, near
 * what a foot carries when three feet hold the robot) and held there. Ground that bears it (at least 90 % of it)
 * for {@code hold} s (default 0.25) is accepted. Ground that gives way is rejected, and the gait chooses another
 * foothold: the sole force (a 30 ms running mean) stays below a quarter of the test force for 50 ms after having
 * passed 60 % of it, or the foot had to go {@code sink} m (default 0.02) further down after first bearing 90 % of
 * the test force (the cell broke under the probe and the foot went on to the bottom of its pit). Ground not found
 * within {@code maxPress} m (default 0.08) is rejected too ("no footing"). While the probe presses, the balance
 * ({@link KeepBalance} with its {@code press}) keeps the body over the three other feet, so a breaking cell costs
 * the robot nothing.
 *
 * <p>Inputs, in Reader order: the gait phase {leg, in the air, probe attempt (a new positive number for every
 * foothold the gait waits on, 0 otherwise)} and the sole forces (4, N). Outputs, in Writer order: (0) the press:
 * an offset to add to the feet (12 numbers, only the probed foot's z is non-zero: how far it is lowered) and
 * (1) the verdict {leg, +1 accepted / −1 rejected, the attempt it answers}; the gait reads (1). Outputs connected
 * to Datas named {@code probes}, {@code fragile found} and {@code fragile avoided} get the counts (written when
 * they change): footholds probed; footholds that gave way; of those, the ones the gait replaced at the same
 * touchdown by a foothold that held. Reports every verdict.
 */
public class ProbeGround extends Relation {
    private final double[] press = new double[3 * LEGS];
    private double testForce;
    private double hold;
    private double pressSpeed;
    private double maxPress;

    /** Time constant of the sole force's running mean, s. */
    private static final double SMOOTHING = 0.03;
    /** How long the force must stay collapsed to call the ground given way, s. */
    private static final double GIVE_WAY = 0.05;
    private static final String GAVE_WAY = "gave way";
    /** The counters' Data names (outputs connected by these names get them). */
    static final String PROBES = "probes";
    static final String FRAGILE_FOUND = "fragile found";
    static final String FRAGILE_AVOIDED = "fragile avoided";

    private double force = Double.NaN;
    private double lowSince = Double.NaN;
    private int probing = -1;
    private long attempt;
    private boolean announced;
    private double depth;
    private double last = Double.NaN;
    private double heldSince = Double.NaN;
    private double peak;
    /** How far the foot was lowered when its sole first bore 90 % of the test force, m (NaN before). */
    private double found = Double.NaN;
    private double sink;
    private boolean decided;
    private long accepted;
    private long rejected;
    private long probes;
    private long fragileFound;
    private long fragileAvoided;
    /** The leg whose foothold gave way at this touchdown, until it is accepted elsewhere or the gait steps on. */
    private int gaveWay = -1;

    public static final ParameterSpec<Double> TEST_FORCE = ParameterSpec.number("testForce").unit("N").above(0)
            .defaultValue(55.0).describe("the sole force a foothold must bear").live();
    public static final ParameterSpec<Double> HOLD = ParameterSpec.number("hold").unit("s").above(0).atMost(2)
            .defaultValue(0.25).describe("how long a foothold must bear the test force").live();
    public static final ParameterSpec<Double> PRESS_SPEED = ParameterSpec.number("pressSpeed").unit("m/s").above(0)
            .atMost(1).defaultValue(0.1).describe("how fast the foot is lowered").live();
    public static final ParameterSpec<Double> MAX_PRESS = ParameterSpec.number("maxPress").unit("m").above(0).atMost(0.2)
            .defaultValue(0.08).describe("how far the foot goes down looking for ground").live();
    public static final ParameterSpec<Double> SINK = ParameterSpec.number("sink").unit("m").above(0).atMost(0.1)
            .defaultValue(0.02).describe("how far the foot may sink after bearing the test force before the ground counts as broken").live();

    @Override
    protected void init(NodeParameters p) {
        testForce = TEST_FORCE.read(p);
        hold = HOLD.read(p);
        pressSpeed = PRESS_SPEED.read(p);
        maxPress = MAX_PRESS.read(p);
        sink = SINK.read(p);
    }

    /** Footholds accepted so far. */
    public long accepted() {
        return accepted;
    }

    /** Footholds rejected so far: ground that gave way under the probe. */
    public long rejected() {
        return rejected;
    }

    @Override
    protected void compute(RelationContext c) {
        Value phase = c.input(0);
        Value soles = c.input(1);
        double now = c.seconds();
        double dt = Double.isNaN(last) ? 0 : Math.max(0, now - last);
        last = now;
        if (!announced && c.outputCount() > 1) {
            c.output(1, Value.ofDoubles(-1, 0, 0)); // "no verdict yet": tells the gait that probing is loaded
            writeCounts(c);
            announced = true;
        }
        if (phase == null || soles == null || phase.length() < 3 || soles.length() < LEGS) {
            c.report("waiting for the gait phase and the sole forces");
            return;
        }
        int leg = (int) phase.element(0);
        if (phase.element(2) < 0.5 || leg < 0 || leg >= LEGS) {
            if (probing >= 0) {
                probing = -1;
                attempt = 0;
                depth = 0;
                writePress(c, -1);
            }
            return;
        }
        long attempt = (long) phase.element(2);
        if (attempt != this.attempt) {
            start(leg, attempt);
        }
        if (decided) {
            return;
        }
        // the sole's contact chatters from one millisecond to the next: judge a 30 ms running mean
        double raw = soles.element(leg);
        force = Double.isNaN(force) ? raw : force + (raw - force) * (1 - Math.exp(-dt / SMOOTHING));
        peak = Math.max(peak, force);
        if (peak >= 0.6 * testForce && force < 0.25 * testForce) {
            if (Double.isNaN(lowSince)) {
                lowSince = now;
            }
            if (now - lowSince >= GIVE_WAY) {
                decide(c, leg, -1, String.format(Locale.ROOT, GAVE_WAY + ": %.0f N after %.0f N", force, peak));
                return;
            }
        } else {
            lowSince = Double.NaN;
        }
        if (Double.isNaN(found) && force >= 0.9 * testForce) {
            found = depth; // the ground is here
        }
        if (!Double.isNaN(found) && depth - found >= sink) {
            decide(c, leg, -1, String.format(Locale.ROOT, GAVE_WAY + ": sank %.3f m after bearing %.0f N", depth - found,
                    peak));
            return;
        }
        if (Double.isNaN(heldSince) && force >= testForce) {
            heldSince = now; // the test force is reached: stop lowering, hold the foot where it is
        } else if (!Double.isNaN(heldSince) && force < 0.9 * testForce) {
            heldSince = Double.NaN; // it sagged: press on
        }
        if (!Double.isNaN(heldSince)) {
            if (now - heldSince >= hold) {
                decide(c, leg, +1, String.format(Locale.ROOT, "holds %.0f N", force));
                return;
            }
        } else {
            depth += pressSpeed * dt;
            if (depth >= maxPress) {
                decide(c, leg, -1, String.format(Locale.ROOT, "no footing %.2f m down", maxPress));
                return;
            }
        }
        writePress(c, leg);
    }

    private void start(int leg, long attempt) {
        if (leg != probing) {
            gaveWay = -1; // a new touchdown: a fragile foothold left behind was not avoided by a probed one
        }
        this.attempt = attempt;
        probing = leg;
        depth = 0;
        heldSince = Double.NaN;
        lowSince = Double.NaN;
        force = Double.NaN;
        peak = 0;
        found = Double.NaN;
        decided = false;
    }

    private void decide(RelationContext c, int leg, int verdict, String why) {
        decided = true;
        if (verdict < 0) {
            depth = 0; // lift off ground that gave way; an accepted foot stays pressed until the gait steps on
        }
        probes++;
        if (verdict > 0) {
            accepted++;
            if (gaveWay == leg) {
                fragileAvoided++; // the gait chose another foothold after this one gave way, and it holds
                gaveWay = -1;
            }
        } else {
            rejected++;
            if (why.startsWith(GAVE_WAY)) {
                fragileFound++;
                gaveWay = leg;
            }
        }
        writePress(c, leg);
        if (c.outputCount() > 1) {
            c.output(1, Value.ofDoubles(leg, verdict, attempt));
        }
        writeCounts(c);
        c.report("leg " + leg + (verdict > 0 ? " accepted: " : " rejected: ") + why + "; " + accepted
                + " footholds accepted, " + rejected + " rejected");
    }

    private void writeCounts(RelationContext c) {
        writeCount(c, PROBES, probes);
        writeCount(c, FRAGILE_FOUND, fragileFound);
        writeCount(c, FRAGILE_AVOIDED, fragileAvoided);
    }

    private static void writeCount(RelationContext c, String name, long count) {
        int i = c.outputIndex(name);
        if (i >= 0) {
            c.output(i, Value.of(count));
        }
    }

    private void writePress(RelationContext c, int leg) {
        java.util.Arrays.fill(press, 0);
        if (leg >= 0) {
            press[3 * leg + 2] = -depth;
        }
        c.output(0, Value.ofDoubles(press));
    }
}
