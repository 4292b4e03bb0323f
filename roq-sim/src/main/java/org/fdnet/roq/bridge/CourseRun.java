package org.fdnet.roq.bridge;

import java.nio.file.Path;
import java.util.Locale;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.CourseFormatException;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.roq.sim.SimOptions;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.DrivenClock;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.engine.RuntimeStartException;

/**
 * One stepped run of a RoQ network on a course with seeded sensor noise (as in the demo), measured by ground truth
 * every 10 ms: how far RoQ walked along the course, how far it strayed from its course line and heading (each
 * averaged over {@link CourseMeter#WINDOW} samples, one crawl cycle: the body sways ±0.15 m and ±0.1 rad within a
 * cycle by design), its largest tilt, whether it fell, and which fragile cells broke under a probe and which under a loaded
 * foot ({@link CourseMeter} measures these).
 *
 * @param distance              m walked along x
 * @param trackError            largest |y − y at the start| averaged over a cycle, m
 * @param headingError          largest |yaw − yaw at the start| averaged over a cycle, rad
 * @param finalHeading          yaw at the end minus at the start, rad
 * @param tilt                  largest |roll| or |pitch|, rad
 * @param fallen                FallDetector's latch at the end
 * @param probeBroken           cells that broke under the probed foot while its probe pressed (on purpose)
 * @param loadedBreakthroughs   every other broken cell: under a foot that had been accepted and loaded
 * @param underSwingingFoot     of those, under the foot of the leg in the air ({@link BreakthroughCauses})
 * @param underStandingFoot     of those, under a standing foot
 * @param slidSinceSetDown      of those under a standing foot, the ones whose foot had slid
 *                              {@link BreakthroughCauses#SLID} m or more since it was set down
 */
public record CourseRun(String label, double distance, double trackError, double headingError, double finalHeading,
                 double tilt, boolean fallen, int probeBroken, int loadedBreakthroughs, int underSwingingFoot,
                 int underStandingFoot, int slidSinceSetDown) {
    /** Runs {@code network} on {@code course} for {@code seconds} of simulated time, noise seed {@code noise}. */
    public static CourseRun of(String label, Path network, Course course, int seconds, long noise, String... unloaded)
            throws Exception {
        return of(label, NetworkRepository.load(network), course, seconds, noise, unloaded);
    }

    /** Runs {@code network} (e.g. with changed parameters) on {@code course}. */
    public static CourseRun of(String label, NetworkInfo network, Course course, int seconds, long noise, String... unloaded)
            throws Exception {
        try (RoqSimulator sim = RoqSimulator.open(course, steppedWithNoise(noise));
             RuntimeNetwork net = startStepped(network, unloaded)) {
            SimBridge bridge = SimBridge.stepped(net, sim, 0, 1);
            bridge.run(1);
            SensorSnapshot s = bridge.lastSnapshot();
            double x0 = s.groundTruthBodyPosition(0);
            double yaw0 = s.groundTruthYaw();
            CourseMeter meter = new CourseMeter(s, course.fragileCells());
            double tilt = 0;
            for (int t = 0; t < seconds * 100; t++) {
                bridge.run(10);
                s = bridge.lastSnapshot();
                meter.sample(s, net);
                tilt = Math.max(tilt, Math.max(Math.abs(s.roll()), Math.abs(s.pitch())));
            }
            Value fallen = value(net, "fallen", "main");
            BreakthroughCauses causes = meter.causes();
            return new CourseRun(label, s.groundTruthBodyPosition(0) - x0, meter.maxTrackError(),
                    meter.maxHeadingError(), CourseMeter.angle(s.groundTruthYaw() - yaw0), tilt,
                    fallen != null && fallen.asBoolean(), meter.probeBroken(), meter.loadedBreakthroughs(),
                    causes.swinging(), causes.standing(), causes.slid());
        }
    }

    /** Stepped simulator options with seeded sensor noise, as in the demo, and no range sensors (no Relation reads them). */
    public static SimOptions steppedWithNoise(long noise) {
        return SimOptions.of(SimMode.STEPPED).withNoise(noise).withRangeSensors(false);
    }

    /** Starts {@code network} on a driven clock (for {@link SimBridge#stepped}) with the {@code unloaded} modules unloaded. */
    public static RuntimeNetwork startStepped(NetworkInfo network, String... unloaded) throws RuntimeStartException {
        RuntimeNetwork net = RuntimeNetwork.start(network, RuntimeOptions.defaults().drivenClock(new DrivenClock(0)));
        for (String module : unloaded) {
            if (!net.controller().unload(module).executed()) {
                net.close();
                throw new IllegalStateException("could not unload module " + module + " of " + network.name());
            }
        }
        return net;
    }

    /** The rubble course of the suites ({@link CourseLoader#rubble}). */
    public static Course rubble(long seed) throws CourseFormatException {
        return CourseLoader.rubble(seed);
    }

    static Value value(RuntimeNetwork net, String node, String module) {
        try {
            return net.controller().value(NodeRef.parse(node, module));
        } catch (RuntimeException notLoaded) {
            return null;
        }
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "%s: %.3f m, track %.3f m, heading %.3f (end %.3f) rad, tilt %.3f rad,"
                        + " fallen %s, probe-broken %d, loaded-foot breakthroughs %d (under a swinging foot %d, under a"
                        + " standing foot %d, slid since set down %d)", label, distance, trackError, headingError,
                finalHeading, tilt, fallen, probeBroken, loadedBreakthroughs, underSwingingFoot, underStandingFoot,
                slidSinceSetDown);
    }
}
