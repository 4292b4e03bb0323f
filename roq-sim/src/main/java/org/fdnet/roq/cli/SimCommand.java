package org.fdnet.roq.cli;

import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.CourseFormatException;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.LoopStatistics;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.roq.sim.SimOptions;
import org.fdnet.roq.view.RoqScreenshot;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fdnet sim}: sets the RoQ down on a course with its standing targets, runs it (stepped or in real time),
 * prints a line per simulated second and a summary, and can write a picture of the last snapshot.
 */
@Command(name = "sim", mixinStandardHelpOptions = true,
        description = "Run the simulated RoQ standing on a course; print progress, a summary, optionally a screenshot.")
public final class SimCommand implements Callable<Integer> {
    @Option(names = "--course", defaultValue = "flat",
            description = "built-in course (flat, slope, rubble, fragile) or a course file (default: flat)")
    String course;

    @Option(names = "--seconds", defaultValue = "10", description = "simulated seconds (default 10)")
    int seconds;

    @Option(names = "--realtime", description = "run the 1 kHz real-time loop instead of stepping")
    boolean realtime;

    @Option(names = "--drop", defaultValue = "0", description = "set the robot down this many metres above standing height")
    double drop;

    @Option(names = "--noise", description = "add seeded sensor noise with this seed")
    Long noise;

    @Option(names = "--screenshot", description = "write a PNG of the last snapshot here")
    Path screenshot;

    @Option(names = "--size", defaultValue = "1200x760", description = "screenshot size WxH (default 1200x760)")
    String size;

    @Override
    public Integer call() throws Exception {
        Course c;
        try {
            c = CourseLoader.resolve(course);
        } catch (CourseFormatException e) {
            System.err.println("fdnet sim: " + e.getMessage());
            return 2;
        }
        int[] wh = parseSize(size);
        if (wh == null || seconds < 1) {
            System.err.println("fdnet sim: --size must be WxH (e.g. 1200x760) and --seconds at least 1");
            return 2;
        }
        SimOptions options = SimOptions.of(realtime ? SimMode.REAL_TIME : SimMode.STEPPED).withDropHeight(drop);
        if (noise != null) {
            options = options.withNoise(noise);
        }
        System.out.printf(Locale.ROOT, "fdnet sim: course %s (%s, %d fragile cells), %s mode, %d s%n", c.name(),
                c.terrain().name().toLowerCase(Locale.ROOT), c.fragileCells().size(), options.mode(), seconds);
        SensorSnapshot s = new SensorSnapshot();
        LoopStatistics stats = new LoopStatistics();
        long wall = System.nanoTime();
        try (RoqSimulator sim = RoqSimulator.open(c, options)) {
            for (int second = 1; second <= seconds; second++) {
                if (realtime) {
                    long target = second * 1000L;
                    while (sim.read(s) < target) {
                        Thread.sleep(5);
                    }
                } else {
                    sim.step(1000);
                    sim.read(s);
                }
                System.out.printf(Locale.ROOT,
                        "  t %3.0f s  body z %.3f m  roll %+5.1f°  pitch %+5.1f°  soles %5.1f %5.1f %5.1f %5.1f N  IR %.2f m  broken %d%n",
                        s.simTime(), s.groundTruthBodyPosition(2), Math.toDegrees(s.roll()), Math.toDegrees(s.pitch()),
                        s.footForce(0), s.footForce(1), s.footForce(2), s.footForce(3), s.irRange(), s.brokenCellCount());
            }
            sim.statistics(stats);
            double wallSeconds = (System.nanoTime() - wall) / 1e9;
            System.out.printf(Locale.ROOT, "summary: %d ticks in %.2f s wall (%.1f× real time); standing height %.3f m, "
                            + "body at %.3f m; %d of %d fragile cells broken; commands applied %d, bad %d%n",
                    stats.ticks(), wallSeconds, s.simTime() / wallSeconds, RoqGeometry.standingHeight(),
                    s.groundTruthBodyPosition(2), s.brokenCellCount(), c.fragileCells().size(), stats.commandsApplied(),
                    stats.badCommands());
            if (realtime) {
                System.out.printf(Locale.ROOT, "loop: wake-up latency p50 %d µs, p99 %d µs, max %d µs; longest tick %d µs;"
                                + " overruns %d (max %d µs); SCHED_FIFO %s, mlockall %s, cpu_dma_latency %s%n",
                        stats.latencyPercentileNanos(50) / 1000, stats.latencyPercentileNanos(99) / 1000,
                        stats.maxLatencyNanos() / 1000, stats.maxTickNanos() / 1000, stats.overruns(),
                        stats.maxOverrunNanos() / 1000,
                        yes(stats.schedFifo()), yes(stats.memoryLocked()), yes(stats.dmaLatencyHeld()));
            } else {
                System.out.printf("state hash %016x (stepped runs are reproducible)%n", sim.stateHash());
            }
            if (screenshot != null) {
                RoqScreenshot.write(s, sim.heightfield(), wh[0], wh[1], screenshot);
                System.out.println("screenshot: " + screenshot);
            }
        }
        return 0;
    }

    private static String yes(boolean b) {
        return b ? "yes" : "no";
    }

    private static int[] parseSize(String text) {
        String[] parts = text.toLowerCase(Locale.ROOT).split("x");
        try {
            int w = Integer.parseInt(parts[0]);
            int h = Integer.parseInt(parts[1]);
            return parts.length == 2 && w >= 200 && h >= 150 && w <= 8000 && h <= 8000 ? new int[] {w, h} : null;
        } catch (NumberFormatException | ArrayIndexOutOfBoundsException e) {
            return null;
        }
    }
}
