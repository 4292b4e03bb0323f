package org.fdnet.roq.testkit;

import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.CourseFormatException;
import org.fdnet.roq.sim.CourseLoader;

/**
 * Reads the course a robot test names: a built-in course ({@code flat}, {@code slope}, {@code rubble},
 * {@code fragile}, {@code crossing}), {@code rubble:SEED} (a 4 m × 2 m course of 6 cm blocks 0.25 m wide placed by
 * the seed, RoQ starting 1.5 m before its middle), {@code slope:DEGREES} (level up to x = 0, then the incline to
 * x = 3, negative going down; RoQ starts 0.4 m before it), or the path of a {@code .course} file.
 */
public final class CourseSpec {
    private CourseSpec() {
    }

    /**
     * @param spec the course, as above
     * @return the course
     * @throws IllegalArgumentException naming the spec and what is wrong with it
     */
    public static Course parse(String spec) {
        try {
            if (spec.startsWith("rubble:")) {
                return rubble(Long.parseLong(spec.substring("rubble:".length()).trim()));
            }
            if (spec.startsWith("slope:")) {
                return slope(Double.parseDouble(spec.substring("slope:".length()).trim()));
            }
            return CourseLoader.resolve(spec);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("course '" + spec + "': after 'rubble:' comes a seed (an integer), after"
                    + " 'slope:' an angle in degrees", e);
        } catch (CourseFormatException e) {
            throw new IllegalArgumentException("course '" + spec + "': " + e.getMessage()
                    + " (a built-in name " + CourseLoader.BUILT_IN + ", rubble:SEED, slope:DEGREES or a .course file)", e);
        }
    }

    /**
     * @param seed places the blocks
     * @return the 4 m × 2 m rubble course of 6 cm blocks that {@code rubble:SEED} names
     * @throws CourseFormatException never for a valid seed; declared by the course reader
     */
    public static Course rubble(long seed) throws CourseFormatException {
        return CourseLoader.rubble(seed);
    }

    /**
     * @param degrees the incline after x = 0, negative going down
     * @return the course that {@code slope:DEGREES} names
     * @throws CourseFormatException when the angle is outside what the course reader accepts
     */
    public static Course slope(double degrees) throws CourseFormatException {
        return CourseLoader.slope(degrees);
    }
}
