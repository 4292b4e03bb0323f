package org.fdnet.roq.cli;

import java.util.Locale;
import java.util.concurrent.Callable;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.CourseFormatException;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.JointCommand;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fdnet bench sim}: the stepped tick (command slot, 12 servos with their motor model, mj_step, sensors,
 * fragile cells, publish) beside a bare {@code mj_step} loop of the same model from the same state, in the same
 * run. The two alternate second by second so the machine's load falls on both alike.
 */
@Command(name = "sim", mixinStandardHelpOptions = true,
        description = "Stepped simulation speed (sim s per wall s) beside a bare mj_step loop (same model, same run).")
public final class BenchSimCommand implements Callable<Integer> {
    @Option(names = "--seconds", defaultValue = "60", description = "simulated seconds for each of the two (default 60)")
    int seconds;

    @Option(names = "--course", defaultValue = "fragile", description = "course (default: fragile, rubble with fragile cells)")
    String course;

    @Override
    public Integer call() throws Exception {
        Course c;
        try {
            c = CourseLoader.resolve(course);
        } catch (CourseFormatException e) {
            System.err.println("fdnet bench sim: " + e.getMessage());
            return 2;
        }
        System.out.printf(Locale.ROOT, "fdnet bench sim: course %s, %d simulated s of each, 1 ms steps, alternating%n",
                c.name(), seconds);
        long plantNanos = 0;
        long bareNanos = 0;
        try (RoqSimulator sim = RoqSimulator.open(c, SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            JointCommand command = new JointCommand();
            sim.step(1000); // warm-up: caches, JIT of read/send
            sim.bareStepNanos(1000);
            for (int second = 1; second <= seconds; second++) {
                long t0 = System.nanoTime();
                for (int k = 0; k < 100; k++) { // the network's rate: a snapshot read and a command every 10 ticks
                    sim.step(10);
                    sim.read(s);
                    command.basedOnTick(s.tick());
                    sim.send(command);
                }
                plantNanos += System.nanoTime() - t0;
                bareNanos += sim.bareStepNanos(1000);
                if (second % 10 == 0 || second == seconds) {
                    System.out.printf(Locale.ROOT, "  %3d s: tick %.1f µs, bare mj_step %.1f µs%n", second,
                            plantNanos / 1e3 / (second * 1000.0), bareNanos / 1e3 / (second * 1000.0));
                }
            }
        }
        double plant = seconds / (plantNanos / 1e9);
        double bare = seconds / (bareNanos / 1e9);
        System.out.printf(Locale.ROOT, "baseline: bare mj_step loop      %8.1f sim s per wall s (%.1f µs per step)%n",
                bare, bareNanos / 1e3 / (seconds * 1000.0));
        System.out.printf(Locale.ROOT, "roq-sim stepped tick            %8.1f sim s per wall s (%.1f µs per tick)%n",
                plant, plantNanos / 1e3 / (seconds * 1000.0));
        double ratio = plant / bare;
        System.out.printf(Locale.ROOT, "ratio %.2f× bare (target ≥ 0.9: %s); %.1f× real time (target ≥ 10: %s)%n", ratio,
                ratio >= 0.9 ? "met" : "NOT met", plant, plant >= 10 ? "met" : "NOT met");
        return 0;
    }
}
