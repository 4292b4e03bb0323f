package org.fdnet.roq.testkit;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/** The run a {@link SimulatedRoq} parameter of a {@link RoqTest} gets: network, course, noise seed. */
@Documented
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.PARAMETER)
public @interface Roq {
    /** @return the {@code .fdn} file, relative to the directory the tests run in (the project's) or absolute */
    String network();

    /** @return the course: a built-in name, {@code rubble:SEED}, {@code slope:DEGREES} or a {@code .course} path */
    String course() default "flat";

    /** @return the sensor-noise seed */
    long noise() default 1;

    /** @return false to turn sensor noise off (every sensor reads the plant exactly; {@link #noise()} is ignored) */
    boolean sensorNoise() default true;

    /** @return modules to unload before the run starts */
    String[] unload() default {};
}
