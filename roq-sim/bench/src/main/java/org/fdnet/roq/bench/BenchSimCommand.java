package org.fdnet.roq.bench;

import java.util.Locale;
import java.util.concurrent.Callable;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.CourseFormatException;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.JointCommand;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.roq.sim.SimOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fdnet bench sim}: stepped speed of the plant and servos (command slot, 12 servos with their motor model,
 * mj_step, joint/inclinometer/sole sensors, fragile cells, publish) beside a bare {@code mj_step} loop of the same
 * model from the same state, in the same run; and, for the record, the full tick with the range sensors' rays
 * (infrared, ultrasonic, depth image) too. The three alternate second by second so the machine's load falls on
 * all alike.
 */
@Command(name = "sim", mixinStandardHelpOptions = true,
        description = "Stepped simulation speed (sim s per wall s) beside a bare mj_step loop (same model, same run).")
public final class BenchSimCommand implements Callable<Integer> {
    @Option(names = "--seconds", defaultValue = "60", description = "simulated seconds for each (default 60)")
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
        if (seconds < 1) {
            System.err.println("fdnet bench sim: --seconds must be at least 1");
            return 2;
        }
        System.out.printf(Locale.ROOT, "fdnet bench sim: course %s, %d simulated s of each, 1 ms steps, alternating%n",
                c.name(), seconds);
        long plantNanos = 0;
        long fullNanos = 0;
        long bareNanos = 0;
        try (RoqSimulator plant = RoqSimulator.open(c, SimOptions.of(SimMode.STEPPED).withRangeSensors(false));
             RoqSimulator full = RoqSimulator.open(c, SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            JointCommand command = new JointCommand();
            run(plant, s, command); // warm-up: caches, JIT of read/send
            run(full, s, command);
            plant.bareStepNanos(1000);
            for (int second = 1; second <= seconds; second++) {
                plantNanos += run(plant, s, command);
                bareNanos += plant.bareStepNanos(1000);
                fullNanos += run(full, s, command);
                if (second % 10 == 0 || second == seconds) {
                    double n = second * 1000.0;
                    System.out.printf(Locale.ROOT, "  %3d s: plant+servos %.1f µs, bare mj_step %.1f µs, full tick %.1f µs%n",
                            second, plantNanos / 1e3 / n, bareNanos / 1e3 / n, fullNanos / 1e3 / n);
                }
            }
        }
        double bare = seconds / (bareNanos / 1e9);
        double plant = seconds / (plantNanos / 1e9);
        double full = seconds / (fullNanos / 1e9);
        double n = seconds * 1000.0;
        System.out.printf(Locale.ROOT, "baseline: bare mj_step loop           %6.1f sim s per wall s (%.1f µs per step)%n",
                bare, bareNanos / 1e3 / n);
        System.out.printf(Locale.ROOT, "plant + servos (stepped tick)        %6.1f sim s per wall s (%.1f µs per tick)%n",
                plant, plantNanos / 1e3 / n);
        System.out.printf(Locale.ROOT, "full tick with IR, sonar, depth rays %6.1f sim s per wall s (%.1f µs per tick, %.2f× bare)%n",
                full, fullNanos / 1e3 / n, full / bare);
        // The verdict is on the tick as shipped (range sensors on: what every simulator opens with unless told);
        // plant + servos alone is printed above for comparison with earlier figures.
        double ratio = full / bare;
        System.out.printf(Locale.ROOT, "tick as shipped (range sensors on): %.2f× bare (target ≥ 0.9: %s); %.1f× real time"
                + " (target ≥ 10: %s); plant + servos alone %.2f× bare%n",
                ratio, ratio >= 0.9 ? "met" : "NOT met", full, full >= 10 ? "met" : "NOT met", plant / bare);
        return 0;
    }

    /** 1000 ticks as a network drives them: a snapshot read and a command every 10 ticks. Returns nanoseconds. */
    private static long run(RoqSimulator sim, SensorSnapshot s, JointCommand command) {
        long t0 = System.nanoTime();
        for (int k = 0; k < 100; k++) {
            sim.step(10);
            sim.read(s);
            command.basedOnTick(s.tick());
            sim.send(command);
        }
        return System.nanoTime() - t0;
    }
}
