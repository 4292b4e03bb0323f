package org.fdnet.roq.bench;

import java.time.Duration;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.testkit.RoqMeasures;
import org.fdnet.roq.testkit.SimulatedRoq;
import org.fdnet.runtime.Value;

/**
 * One robot run of the sweeps, as a user's robot test runs it: {@code network} on {@code course} with seeded sensor
 * noise, some modules unloaded, for a number of simulated seconds on a {@link SimulatedRoq}; what the kit measured.
 *
 * @param label       what the sweep calls the run
 * @param measures    the kit's ground-truth measures at the end
 * @param slackTicks  the network's count of stance ticks below the minimum sole force (its Data {@value #SLACK}),
 *                    or −1 when it has none
 * @param strainedTicks the 10 ms steps at whose end some joint's motor gave all the torque it has (ground truth): a
 *                    leg that cannot hold the posture it is commanded to — its foot given a place out of its reach,
 *                    or more load than it can carry there
 */
record MeasuredWalk(String label, RoqMeasures measures, long slackTicks, long strainedTicks) {
    /** The Data a force-distributing network counts its slack stance ticks in. */
    static final String SLACK = "Forces/slack ticks";
    /** A joint's torque counts as at the motor's limit from this part of it on. */
    static final double AT_LIMIT = 0.98;

    /** Runs {@code network} on {@code course} for {@code seconds} of simulated time, noise seed {@code noise}. */
    static MeasuredWalk of(String label, NetworkInfo network, Course course, int seconds, long noise,
                           String... unloaded) {
        try (SimulatedRoq roq = SimulatedRoq.builder().network(network).course(course).noise(noise).unload(unloaded)
                .start()) {
            long[] strained = new long[1];
            double limit = AT_LIMIT * RoqGeometry.maxJointTorque();
            roq.afterEachStep(r -> strained[0] += anyJointAt(r.snapshot(), limit) ? 1 : 0);
            roq.runFor(Duration.ofSeconds(seconds));
            return new MeasuredWalk(label, roq.measures(), slackTicks(roq), strained[0]);
        }
    }

    /** Whether some joint's torque in {@code s} is {@code limit} N·m or more either way. */
    static boolean anyJointAt(SensorSnapshot s, double limit) {
        for (int j = 0; j < RoqGeometry.JOINTS; j++) {
            if (Math.abs(s.jointTorque(j)) >= limit) {
                return true;
            }
        }
        return false;
    }

    private static long slackTicks(SimulatedRoq roq) {
        try {
            Value v = roq.network().value(SLACK);
            return v == null ? 0 : v.asLong();
        } catch (IllegalArgumentException noSuchData) {
            return -1; // a network without a force distribution counts no slack ticks
        }
    }

    @Override
    public String toString() {
        return label + ": " + measures + (slackTicks >= 0 ? ", " + slackTicks + " stance ticks below the least sole force"
                : "") + ", " + strainedTicks + " steps with a joint at its torque limit";
    }
}
