package org.fdnet.roq.view;

import java.util.Locale;

/**
 * The live figures of a demo run at one moment, as the progress line, the summary and the demo window show them.
 * A figure the network does not provide is {@code NaN} (margin) or negative (counts) and shows as "n/a".
 *
 * @param simTime          simulated time, s
 * @param distance         forward distance walked, m
 * @param margin           the last stability margin KeepBalance reported, m
 * @param smallestMargin   the smallest margin reported so far, m
 * @param probes           probes of the ground made (a Probing module's count)
 * @param fragileFound     fragile cells found by probing
 * @param fragileAvoided   fragile cells avoided
 * @param brokenCells      cells broken through (the simulator's count)
 * @param events           events the network logged
 * @param loopP99Micros    the joint loop's wake-up p99, µs
 * @param overruns         the joint loop's overruns
 * @param fallen           whether the fall detector says the robot fell
 */
public record DemoFigures(double simTime, double distance, double margin, double smallestMargin, long probes,
                          long fragileFound, long fragileAvoided, int brokenCells, long events, double loopP99Micros,
                          long overruns, boolean fallen) {

    /** Figures before the first snapshot. */
    public static DemoFigures none() {
        return new DemoFigures(0, 0, Double.NaN, Double.NaN, -1, -1, -1, 0, 0, 0, 0, false);
    }

    /** A margin in m, or "n/a". */
    public static String metres(double m) {
        return Double.isNaN(m) ? "n/a" : String.format(Locale.ROOT, "%.3f m", m);
    }

    /** A count, or "n/a" when negative. */
    public static String count(long n) {
        return n < 0 ? "n/a" : String.format(Locale.ROOT, "%,d", n);
    }

    /** The one-line progress report, each second. */
    public String progressLine() {
        return String.format(Locale.ROOT, "  t=%5.1f s  distance %.3f m  margin %s  probes %s  fragile found %s"
                        + " avoided %s  broken %d  events %,d%s", simTime, distance, metres(margin), count(probes),
                count(fragileFound), count(fragileAvoided), brokenCells, events, fallen ? "  FALLEN" : "");
    }
}
