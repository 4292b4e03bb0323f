package org.fdnet.roq.testkit;

import java.util.Locale;

/**
 * What a robot test measured so far, by ground truth sampled every 10 ms of simulated time (the network never sees
 * these figures; they are the test's view of the world).
 *
 * @param time                    simulated time since the run started, s
 * @param distance                m walked along the course (x) since the start
 * @param trackError              largest distance from the course line (y at the start), averaged over one crawl
 *                                cycle (4.5 s: the body sways within a cycle by design), m
 * @param headingError            largest |yaw − yaw at the start|, averaged over a cycle, rad
 * @param tilt                    largest |roll| or |pitch| of any sample, rad
 * @param fallen                  whether RoQ fell: the network's {@code fallen} Data when it has one, else a tilt
 *                                above {@link SimulatedRoq#FALLEN_TILT} at any sample
 * @param probeBroken             fragile cells broken under a probing foot while its probe pressed (on purpose)
 * @param loadedBreakthroughs     every other broken fragile cell: under a foot that was accepted and loaded
 * @param underSwingingFoot       of those, under the foot of the leg in the air
 * @param underStandingFoot       of those, under a standing foot
 * @param slidSinceSetDown        of those under a standing foot, the ones whose foot had slid 2 cm or more since set
 *                                down
 * @param smallestStabilityMargin smallest value of the network's Data named {@code margin} after its first change
 *                                (m), or NaN when the network has no such Data
 */
public record RoqMeasures(double time, double distance, double trackError, double headingError, double tilt,
                          boolean fallen, int probeBroken, int loadedBreakthroughs, int underSwingingFoot,
                          int underStandingFoot, int slidSinceSetDown, double smallestStabilityMargin) {
    @Override
    public String toString() {
        return String.format(Locale.ROOT, "t = %.2f s: %.3f m walked, track error %.3f m, heading error %.3f rad, tilt"
                        + " %.3f rad, %s, %d crusts broken by probes, %d loaded-foot breakthroughs (swinging %d,"
                        + " standing %d, slid %d), smallest margin %s", time, distance, trackError, headingError, tilt,
                fallen ? "FELL" : "no fall", probeBroken, loadedBreakthroughs, underSwingingFoot, underStandingFoot,
                slidSinceSetDown, Double.isNaN(smallestStabilityMargin) ? "n/a"
                        : String.format(Locale.ROOT, "%.3f m", smallestStabilityMargin));
    }
}
